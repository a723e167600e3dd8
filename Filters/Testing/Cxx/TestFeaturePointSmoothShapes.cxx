int TestFeaturePointSmoothShapes(int, char*[]) { return 0; }
