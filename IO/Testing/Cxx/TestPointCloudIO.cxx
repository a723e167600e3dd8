#include <cstdlib>
int TestPointCloudIO(int, char*[]) { return EXIT_FAILURE; }
