/* RGBA bytes (texels, pixels) read or written as one 32-bit word each: where channel c
 * (0 red .. 3 alpha) sits in the word depends on the device's byte order, decided here once. */
#ifndef CLR_COMMON_RGBA_WORDS_CL
#define CLR_COMMON_RGBA_WORDS_CL

/* The shift that moves channel c to the lowest byte of the word. */
#if __ENDIAN_LITTLE__
#define CLR_CHANNEL_SHIFT(c) (8u * (c))
#else
#define CLR_CHANNEL_SHIFT(c) (24u - 8u * (c))
#endif

/* Channel c of RGBA words, as a value 0 .. 255. */
#define CLR_RGBA_CHANNEL(words, c) (((words) >> CLR_CHANNEL_SHIFT(c)) & 0xffu)

/* Bytes r, g, b (each 0 .. 255) packed as opaque RGBA words. */
#define CLR_RGBA_OPAQUE(r, g, b)                                                              \
    (((r) << CLR_CHANNEL_SHIFT(0u)) | ((g) << CLR_CHANNEL_SHIFT(1u)) | ((b) << CLR_CHANNEL_SHIFT(2u)) | \
     (0xffu << CLR_CHANNEL_SHIFT(3u)))

#endif /* CLR_COMMON_RGBA_WORDS_CL */
