#include <cstdlib>
int TestPointCloudText(int, char*[]) { return EXIT_FAILURE; }
