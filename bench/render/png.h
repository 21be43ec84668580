/* png.h: writing an 8-bit RGBA image as PNG without a library (zlib stored blocks, CRC-32 and
 * Adler-32 computed here). */
#ifndef RENDER_PNG_H
#define RENDER_PNG_H

#include <stddef.h>
#include <stdint.h>

/* Writes the w x h image rgba (4 bytes a pixel, rows top to bottom) to path. Returns 0, or -1
 * with a message in err (size errsz). */
int png_write(const char *path, const uint8_t *rgba, uint32_t w, uint32_t h, char *err,
              size_t errsz);

#endif
