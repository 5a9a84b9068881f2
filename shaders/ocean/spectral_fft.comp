// One pass of the spectral ocean's inverse 2D FFT: every row (or, with
// SWELL_FFT_VERTICAL 1, every column) of every cascade, one workgroup each,
// transformed in place through shared memory: radix-2 decimation in time,
// inputs in bit-reversed order, log2(N) stages of butterflies with
// twiddles exp(+2 pi i j / size) (the inverse transform, unnormalised, as
// the CPU twin's kissfft computes it). Each sample carries two complex
// numbers per image, so one pass transforms all four packed fields.
#include "swell/shader_constants.h"

layout(local_size_x = SWELL_FFT_SIZE) in;

layout(binding = 2, rgba32f) uniform image2DArray spectrumA;
layout(binding = 3, rgba32f) uniform image2DArray spectrumB;

shared vec4 bufferA[2][SWELL_FFT_SIZE];
shared vec4 bufferB[2][SWELL_FFT_SIZE];

ivec3 sampleAt(int i)
{
    int line = int(gl_WorkGroupID.x), cascade = int(gl_WorkGroupID.y);
#if SWELL_FFT_VERTICAL
    return ivec3(line, i, cascade);
#else
    return ivec3(i, line, cascade);
#endif
}

// Two complex numbers (xy, zw) times one (w).
vec4 cmul2(vec2 w, vec4 v) { return vec4(w.x * v.x - w.y * v.y, w.x * v.y + w.y * v.x, w.x * v.z - w.y * v.w, w.x * v.w + w.y * v.z); }

void main()
{
    int i = int(gl_LocalInvocationID.x);
    int reversed = int(bitfieldReverse(uint(i)) >> (32 - SWELL_FFT_LOG2_SIZE));
    bufferA[0][reversed] = imageLoad(spectrumA, sampleAt(i));
    bufferB[0][reversed] = imageLoad(spectrumB, sampleAt(i));
    barrier();
    int from = 0;
    for (int half_size = 1; half_size < SWELL_FFT_SIZE; half_size *= 2) {
        int j = i & (2 * half_size - 1);
        int even = i - j + (j & (half_size - 1));
        int odd = even + half_size;
        float angle = 3.14159265358979 * float(j & (half_size - 1)) / float(half_size);
        vec2 w = vec2(cos(angle), sin(angle));
        float sign = j < half_size ? 1.0 : -1.0;
        vec4 a = bufferA[from][even] + sign * cmul2(w, bufferA[from][odd]);
        vec4 b = bufferB[from][even] + sign * cmul2(w, bufferB[from][odd]);
        bufferA[1 - from][i] = a;
        bufferB[1 - from][i] = b;
        from = 1 - from;
        barrier();
    }
    imageStore(spectrumA, sampleAt(i), bufferA[from][i]);
    imageStore(spectrumB, sampleAt(i), bufferB[from][i]);
}
