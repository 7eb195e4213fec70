// Cost decomposition of the compute TAAU (scripts/measure-compute-upscale.sh
// --decompose), not part of the sample: as TemporalNoNeighbourhoodCS.hlsl,
// and the history's five Catmull-Rom taps and its bilinear tap made from that
// one texel too, so that only the arithmetic is left of the pass's reads.
// Its image is wrong; only its time counts.
#define TEMPORAL_NO_HISTORY 1
#include "TemporalNoNeighbourhoodCS.hlsl"
