/* CELL ARRAY (2D, a rectangle given by two opposite corners P and Q in any order) and CELL ARRAY 3
 * (a parallelogram P, Q, R) on the offscreen type (lavapipe) and the PDF type: random rectangles
 * and parallelograms of 1..4 x 1..4 cells, each cell's colour index drawn at its centre in both
 * pictures, the background just outside. Cell (i, j) of the colour array lies from P i columns
 * toward Q (in x for the 2D form) and j rows toward R (in y). Links libpng besides libphigs to read
 * the PNG. argv[1]: a directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

static const float colours[7][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                    {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};

static void set_colours(Pint ws) {
    for (Pint i = 1; i < 7; ++i) {
        Pcolr_rep rep;
        rep.rgb.red = colours[i][0], rep.rgb.green = colours[i][1], rep.rgb.blue = colours[i][2];
        EXPECT_NO_ERROR(pset_colr_rep(ws, i, &rep));
    }
}

/* Whether the pixel at NPC (x, y) has the colour of index `index`. */
static int shows(const Picture* p, double x, double y, int index) {
    const unsigned char* c = picture_pixel(p, x, y);
    for (int k = 0; k < 3; ++k)
        if (abs(c[k] - (int)(255 * colours[index][k])) > 40) return 0;
    return 1;
}

typedef struct {
    double p[2], du[2], dv[2]; /* the first cell's corner and the array's two sides */
    int columns, rows;
    Pint cells[16];
} CellLayout;

/* Draws `layout` (through CELL ARRAY when twoD, else CELL ARRAY 3) and checks both pictures. */
static void check_layout(const CellLayout* layout, int twoD, const char* dir, int trial) {
    char stem[64];
    Picture pictures[2];
    Ppat_rep rep = {{layout->columns, layout->rows}, (Pint*)layout->cells};
    snprintf(stem, sizeof stem, "cell_arrays_%d", trial);
    const PictureFiles files = picture_files(dir, stem);
    EXPECT_NO_ERROR(popen_struct(1));
    if (twoD) {
        Prect rect = {{(Pfloat)layout->p[0], (Pfloat)layout->p[1]},
                      {(Pfloat)(layout->p[0] + layout->du[0]), (Pfloat)(layout->p[1] + layout->dv[1])}};
        EXPECT_NO_ERROR(pcell_array(&rect, &rep));
    } else {
        Pparal paral = {{(Pfloat)layout->p[0], (Pfloat)layout->p[1], 0},
                        {(Pfloat)(layout->p[0] + layout->du[0]), (Pfloat)(layout->p[1] + layout->du[1]), 0},
                        {(Pfloat)(layout->p[0] + layout->dv[0]), (Pfloat)(layout->p[1] + layout->dv[1]), 0}};
        EXPECT_NO_ERROR(pcell_array3(&paral, &rep));
    }
    EXPECT_NO_ERROR(pclose_struct());
    CHECK(draw_offscreen_and_pdf_with(&files, pictures, set_colours));
    for (int k = 0; k < 2 && pictures[k].rgb; ++k) {
        const int failed = failures;
        for (int j = 0; j < layout->rows; ++j)
            for (int i = 0; i < layout->columns; ++i) {
                const double a = (i + 0.5) / layout->columns, b = (j + 0.5) / layout->rows;
                const double x = layout->p[0] + a * layout->du[0] + b * layout->dv[0];
                const double y = layout->p[1] + a * layout->du[1] + b * layout->dv[1];
                CHECK(shows(&pictures[k], x, y, layout->cells[j * layout->columns + i]));
            }
        /* Past the far corner from P, along the diagonal: background. */
        const double x = layout->p[0] + 1.08 * (layout->du[0] + layout->dv[0]);
        const double y = layout->p[1] + 1.08 * (layout->du[1] + layout->dv[1]);
        CHECK(shows(&pictures[k], x, y, 0));
        if (failures != failed)
            fprintf(stderr, "  trial %d (%s form, %d x %d cells) in the %s picture\n", trial,
                    twoD ? "2D" : "3D", layout->columns, layout->rows, pictures[k].name);
        free(pictures[k].rgb);
    }
    EXPECT_NO_ERROR(pdel_struct(1));
}

/* A random layout inside NPC [0.15, 0.85]^2: for the 2D form an axis-aligned rectangle whose P may
 * be any corner, for the 3D form a parallelogram. */
static CellLayout random_layout(int twoD) {
    CellLayout layout;
    layout.columns = 1 + (int)(next_random() % 4);
    layout.rows = 1 + (int)(next_random() % 4);
    for (int k = 0; k < layout.columns * layout.rows; ++k) layout.cells[k] = 1 + (Pint)(next_random() % 6);
    const double width = random_real(0.3, 0.55), height = random_real(0.3, 0.55);
    const int flipX = (int)(next_random() % 2), flipY = (int)(next_random() % 2);
    layout.p[0] = flipX ? 0.2 + width : 0.2;
    layout.p[1] = flipY ? 0.2 + height : 0.2;
    layout.du[0] = flipX ? -width : width, layout.du[1] = 0;
    layout.dv[0] = 0, layout.dv[1] = flipY ? -height : height;
    if (!twoD) layout.dv[0] = random_real(-0.08, 0.08), layout.du[1] = random_real(-0.08, 0.08);
    return layout;
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    snprintf(errors, sizeof errors, "%s/cell_arrays_errors.txt", dir);
    open_with_handler(errors);
    seed_random(20261207);
    for (int trial = 0; trial < 8; ++trial) {
        const int twoD = trial % 2 == 0;
        const CellLayout layout = random_layout(twoD);
        check_layout(&layout, twoD, dir, trial);
    }
    pclose_phigs();
    return finish("test_cell_arrays");
}
