/* Pictures the C tests read back: the PNG files of the offscreen workstation type and the binary
 * PPM files pdftoppm makes of the PDF type's pages, both as RGB bytes, rows top to bottom. */
#ifndef PHIGS_C_TEST_PICTURE_H
#define PHIGS_C_TEST_PICTURE_H

#include <png.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int width, height;
    unsigned char* rgb; /* rows top to bottom */
    double side;        /* where a test addresses pixels by NPC: [0, 1]^2 is the lower left
                           side x side pixels */
    const char* name;   /* for messages */
} Picture;

/* Reads a PNG file as RGB into `out` (its rgb to be freed); 0 when it cannot. */
static inline int read_png(const char* path, Picture* out) {
    png_image image;
    memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path)) return 0;
    image.format = PNG_FORMAT_RGB;
    out->width = (int)image.width, out->height = (int)image.height;
    out->rgb = malloc(PNG_IMAGE_SIZE(image));
    return out->rgb && png_image_finish_read(&image, NULL, out->rgb, 0, NULL);
}

/* Reads a binary PPM file (P6, maxval 255) as pdftoppm writes it; 0 when it cannot. */
static inline int read_ppm(const char* path, Picture* out) {
    FILE* f = fopen(path, "rb");
    int maxval = 0;
    if (!f) return 0;
    if (fscanf(f, "P6 %d %d %d", &out->width, &out->height, &maxval) != 3 || maxval != 255) {
        fclose(f);
        return 0;
    }
    fgetc(f);
    const size_t size = (size_t)out->width * (size_t)out->height * 3;
    out->rgb = malloc(size);
    const int ok = out->rgb && fread(out->rgb, 1, size, f) == size;
    fclose(f);
    return ok;
}

#endif
