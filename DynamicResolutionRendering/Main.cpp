// Entry point of the DynamicResolutionRendering executable.
#include "DynamicResolutionRendering.h"

int main(int argc, char** argv) { return drr::SampleMain(argc, argv); }
