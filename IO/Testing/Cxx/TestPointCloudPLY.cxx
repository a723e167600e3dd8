// STUB, to be replaced.
#include <cstdlib>
int TestPointCloudPLY(int, char*[]) { return EXIT_FAILURE; }
