/* png.c: the PNG writer: signature, IHDR, one IDAT of zlib stored blocks (filter 0 on every
 * row), IEND; each chunk with its CRC-32. */
#include "png.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PNG_STORED_MAX 65535u

static uint32_t crc_table[256];

static void crc_init(void)
{
    for (uint32_t n = 0; n < 256; n++) {
        uint32_t c = n;
        for (int k = 0; k < 8; k++)
            c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        crc_table[n] = c;
    }
}

static uint32_t crc32_update(uint32_t crc, const uint8_t *p, size_t n)
{
    for (size_t i = 0; i < n; i++)
        crc = crc_table[(crc ^ p[i]) & 0xFF] ^ (crc >> 8);
    return crc;
}

static void be32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24);
    p[1] = (uint8_t)(v >> 16);
    p[2] = (uint8_t)(v >> 8);
    p[3] = (uint8_t)v;
}

/* Writes one chunk: length, type, data, CRC of type and data. */
static int chunk(FILE *f, const char type[4], const uint8_t *data, uint32_t len)
{
    uint8_t hdr[8], tail[4];
    uint32_t crc = 0xFFFFFFFFu;
    be32(hdr, len);
    memcpy(hdr + 4, type, 4);
    crc = crc32_update(crc, hdr + 4, 4);
    crc = crc32_update(crc, data, len);
    be32(tail, crc ^ 0xFFFFFFFFu);
    return fwrite(hdr, 1, 8, f) == 8 && (len == 0 || fwrite(data, 1, len, f) == len) &&
                   fwrite(tail, 1, 4, f) == 4
               ? 0
               : -1;
}

/* The zlib stream of raw (n bytes) in stored blocks; returns its size, written into z. */
static size_t zlib_stored(uint8_t *z, const uint8_t *raw, size_t n)
{
    uint32_t a = 1, b = 0;
    size_t o = 0, i = 0;
    z[o++] = 0x78;
    z[o++] = 0x01;
    do {
        size_t len = n - i < PNG_STORED_MAX ? n - i : PNG_STORED_MAX;
        z[o++] = i + len == n; /* BFINAL on the last block, BTYPE 00 */
        z[o++] = (uint8_t)len;
        z[o++] = (uint8_t)(len >> 8);
        z[o++] = (uint8_t)~len;
        z[o++] = (uint8_t)(~len >> 8);
        memcpy(z + o, raw + i, len);
        o += len;
        i += len;
    } while (i < n);
    for (i = 0; i < n; i++) {
        a = (a + raw[i]) % 65521u;
        b = (b + a) % 65521u;
    }
    be32(z + o, (b << 16) | a);
    return o + 4;
}

int png_write(const char *path, const uint8_t *rgba, uint32_t w, uint32_t h, char *err,
              size_t errsz)
{
    static const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    size_t row = (size_t)w * 4 + 1, n = row * h, zn;
    uint8_t ihdr[13], *raw = malloc(n), *z = malloc(n + 5 * (n / PNG_STORED_MAX + 1) + 6);
    FILE *f = NULL;
    int rc = -1;
    if (!raw || !z) {
        snprintf(err, errsz, "out of memory writing %s", path);
        goto done;
    }
    for (uint32_t y = 0; y < h; y++) {
        raw[y * row] = 0;
        memcpy(raw + y * row + 1, rgba + (size_t)y * w * 4, (size_t)w * 4);
    }
    zn = zlib_stored(z, raw, n);
    be32(ihdr, w);
    be32(ihdr + 4, h);
    memcpy(ihdr + 8, "\x08\x06\x00\x00\x00", 5); /* 8 bits, RGBA, deflate, filters, no interlace */
    crc_init();
    if (!(f = fopen(path, "wb")) || fwrite(sig, 1, 8, f) != 8 || chunk(f, "IHDR", ihdr, 13) ||
        chunk(f, "IDAT", z, (uint32_t)zn) || chunk(f, "IEND", NULL, 0) || fflush(f)) {
        snprintf(err, errsz, "cannot write %s: %s", path, strerror(errno));
        goto done;
    }
    rc = 0;
done:
    if (f && fclose(f) && rc == 0) {
        snprintf(err, errsz, "cannot write %s: %s", path, strerror(errno));
        rc = -1;
    }
    free(raw);
    free(z);
    return rc;
}
