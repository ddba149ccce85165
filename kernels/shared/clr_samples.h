/*
 * Where in a pixel its samples lie (anti-aliasing), shared textually by the kernels and the
 * host reference so that both trace exactly the same rays. One sample sits at the pixel's
 * centre. Several form a rank-1 lattice (stratified in x and in y for any count, and well
 * spread in 2D), shifted by a per-pixel random offset (Cranley-Patterson rotation) from an
 * integer hash of the pixel, the frame's seed and nothing else: deterministic for a given
 * seed and frame, and without the same pattern repeating in every pixel.
 */
#ifndef CLR_SAMPLES_H
#define CLR_SAMPLES_H

#ifdef __OPENCL_VERSION__
/* No fused multiply-adds, as on the host: both must pick the same sample points. */
#pragma OPENCL FP_CONTRACT OFF
#define CLR_INLINE
#define CLR_FLOORF floor
#else
#include <cmath>
#define CLR_INLINE inline
#define CLR_FLOORF std::floor
#endif

/* A well-mixed 32-bit integer hash (two xor-shift-multiply rounds). */
CLR_INLINE unsigned int clr_hash(unsigned int x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

/* x - floor(x), written out so that host and device agree to the bit. */
CLR_INLINE float clr_fraction(float x)
{
    return x - CLR_FLOORF(x);
}

/* The seed of one frame's samples: the scene's seed mixed with the frame index. */
CLR_INLINE unsigned int clr_frame_seed(unsigned int scene_seed, unsigned int frame)
{
    return clr_hash(scene_seed ^ clr_hash(frame + 0x9e3779b9u));
}

/* The generator of the lattice below: about n times the golden ratio's fraction, made coprime
 * with n so that the n samples fall in n different rows. */
CLR_INLINE unsigned int clr_lattice_step(unsigned int n)
{
    unsigned int k = (unsigned int)((float)n * 0.618034f + 0.5f);
    for (;; ++k) {
        unsigned int a = k, b = n;
        while (b != 0) {
            unsigned int r = a % b;
            a = b;
            b = r;
        }
        if (a == 1)
            return k;
    }
}

/* The pixel's random shift of the pattern, in [0, 1): `axis` 0 for x, 1 for y. */
CLR_INLINE float clr_pixel_rotation(unsigned int frame_seed, int col, int row, unsigned int axis)
{
    unsigned int h = clr_hash(frame_seed ^ clr_hash((unsigned int)col * 0x8da6b343u ^ (unsigned int)row * 0xd8163841u));
    if (axis == 1)
        h = clr_hash(h);
    return (float)(h >> 8) * (1.0f / 16777216.0f);
}

/* Offset of sample `sample` of `samples` inside pixel (col, row), each coordinate in [0, 1).
 * One sample: the centre. Several: a rank-1 (Fibonacci-like) lattice, sample i at
 * ((i + 0.5) / n, ((i k mod n) + 0.5) / n), so that every column and every row of an n x n
 * grid holds exactly one sample, shifted by the pixel's rotation. */
CLR_INLINE float clr_sample_offset_x(unsigned int frame_seed, int col, int row, int sample, int samples)
{
    if (samples == 1)
        return 0.5f;
    float x = ((float)sample + 0.5f) / (float)samples;
    return clr_fraction(x + clr_pixel_rotation(frame_seed, col, row, 0));
}

CLR_INLINE float clr_sample_offset_y(unsigned int frame_seed, int col, int row, int sample, int samples)
{
    if (samples == 1)
        return 0.5f;
    unsigned int n = (unsigned int)samples;
    unsigned int rank = ((unsigned int)sample * clr_lattice_step(n)) % n;
    float y = ((float)rank + 0.5f) / (float)samples;
    return clr_fraction(y + clr_pixel_rotation(frame_seed, col, row, 1));
}

#endif /* CLR_SAMPLES_H */
