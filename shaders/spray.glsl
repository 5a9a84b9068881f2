// The spray's counter-based random numbers (spray.vert, spray.geom): a
// value that depends on its key alone, as src/core/counter_random.h's do.
#ifndef SWELL_SPRAY_GLSL
#define SWELL_SPRAY_GLSL

// A 32-bit integer hash (Wellons 2018, "lowbias32"): every input bit
// changes about half the output bits; GLSL's sin-based hashes are not
// specified to the bit.
uint sprayHash(uint x)
{
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

float sprayUnit(uint key, uint n) { return float(sprayHash(key + n * 0x9e3779b9u) >> 8u) * (1.0 / 16777216.0); }

#endif
