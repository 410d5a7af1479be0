/* Pictures the C tests read back: the PNG files of the offscreen workstation type and the binary
 * PPM files pdftoppm makes of the PDF type's pages, both as RGB bytes, rows top to bottom. */
#ifndef PHIGS_C_TEST_PICTURE_H
#define PHIGS_C_TEST_PICTURE_H

#include "check.h"

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

/* The RGB of the pixel at NPC (x, y) of the picture (x, y in [0, 1], scaled by its side). */
static inline const unsigned char* picture_pixel(const Picture* p, double x, double y) {
    const int i = (int)(x * p->side), j = (int)(p->height - y * p->side);
    return p->rgb + ((size_t)j * (size_t)p->width + (size_t)i) * 3;
}

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

/* Where draw_offscreen_and_pdf writes its files (pdftoppm adds ".ppm" to ppm_root). */
typedef struct {
    char png[512], pdf[512], ppm_root[512];
} PictureFiles;

/* The files `dir`/`stem`.png, `dir`/`stem`.pdf and `dir`/`stem`_pdf.ppm. */
static inline PictureFiles picture_files(const char* dir, const char* stem) {
    PictureFiles files;
    snprintf(files.png, sizeof files.png, "%s/%s.png", dir, stem);
    snprintf(files.pdf, sizeof files.pdf, "%s/%s.pdf", dir, stem);
    snprintf(files.ppm_root, sizeof files.ppm_root, "%s/%s_pdf", dir, stem);
    return files;
}

/* Draws structure 1 on a fresh offscreen workstation (1) and PDF workstation (2) and reads both
 * pictures: p[0] the offscreen one (NPC [0, 1]^2 on 768 x 768 pixels), p[1] the PDF page
 * rasterised by pdftoppm at 144 dpi. `setup`, when given, sets each workstation's tables first. */
static inline int draw_offscreen_and_pdf_with(const PictureFiles* files, Picture p[2],
                                              void (*setup)(Pint ws)) {
    char command[2048], ppm[600];
    remove(files->png), remove(files->pdf);
    EXPECT_NO_ERROR(popen_ws(1, files->png, PWST_OFFSCREEN));
    EXPECT_NO_ERROR(popen_ws(2, files->pdf, PWST_PDF));
    for (Pint ws = 1; ws <= 2; ++ws) {
        if (setup) setup(ws);
        EXPECT_NO_ERROR(ppost_struct(ws, 1, 0.5f));
        EXPECT_NO_ERROR(pupd_ws(ws, PFLAG_PERFORM));
        EXPECT_NO_ERROR(pclose_ws(ws));
    }
    p[0].rgb = p[1].rgb = NULL;
    p[0].side = 768, p[0].name = "offscreen";
    p[1].side = 595.2756 * 2, p[1].name = "PDF";
    snprintf(command, sizeof command, "pdftoppm -r 144 -singlefile '%s' '%s'", files->pdf, files->ppm_root);
    snprintf(ppm, sizeof ppm, "%s.ppm", files->ppm_root);
    return read_png(files->png, &p[0]) && system(command) == 0 && read_ppm(ppm, &p[1]);
}

static inline int draw_offscreen_and_pdf(const PictureFiles* files, Picture p[2]) {
    return draw_offscreen_and_pdf_with(files, p, NULL);
}

#endif
