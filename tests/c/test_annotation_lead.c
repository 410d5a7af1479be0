/* ANNOTATION TEXT RELATIVE under annotation style LEAD LINE joins the reference point to the
 * annotation point with a line in the polyline colour, width and linetype in force; UNCONNECTED
 * (and a style the workstation lacks) draws no line. Seeded random reference points, offsets,
 * polyline colours and widths, drawn on the offscreen type (lavapipe, validation layer on) and the
 * PDF type (rasterised by pdftoppm at 144 dpi): points along the way, clear of the text, show the
 * line's colour or the background; a dashed or dotted lead line shows along part of its way only.
 * argv[1]: a directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

static PictureFiles files;

/* Whether a pixel within two of NPC (x, y) has the colour rgb (within 3/255 per component). */
static int colour_near(const Picture* p, double x, double y, const double rgb[3]) {
    const int i0 = (int)(x * p->side), j0 = (int)(p->height - y * p->side);
    for (int j = j0 - 2; j <= j0 + 2; ++j)
        for (int i = i0 - 2; i <= i0 + 2; ++i) {
            const unsigned char* c = p->rgb + ((size_t)j * (size_t)p->width + (size_t)i) * 3;
            int same = 1;
            for (int k = 0; k < 3; ++k) same = same && fabs(c[k] - 255 * rgb[k]) <= 3.5;
            if (same) return 1;
        }
    return 0;
}

/* A random lead line: structure 1 holds one annotation "X" in `style` whose lead line (if drawn)
 * has a random colour (rgb), a width in [width_lo, width_hi] and `linetype`; ref and offset give
 * its way in NPC. */
typedef struct {
    double rgb[3];
    Ppoint ref;
    Pvec offset;
} Lead;

static Lead lead_structure(Pint style, Pint linetype, double width_lo, double width_hi) {
    Lead l;
    for (int k = 0; k < 3; ++k) l.rgb[k] = (double)(64 + next_random() % 192u) / 255.0;
    const double angle = random_real(0.0, 6.283);
    const double length = random_real(0.25, 0.35);
    l.ref.x = (Pfloat)random_real(0.4, 0.6), l.ref.y = (Pfloat)random_real(0.4, 0.6);
    l.offset.delta_x = (Pfloat)(length * cos(angle)), l.offset.delta_y = (Pfloat)(length * sin(angle));
    Pgcolr colour;
    colour.type = PMODEL_RGB;
    colour.val.general.x = (Pfloat)l.rgb[0], colour.val.general.y = (Pfloat)l.rgb[1],
    colour.val.general.z = (Pfloat)l.rgb[2];
    pdel_struct(1);
    popen_struct(1);
    pset_line_colr(&colour);
    pset_linewidth((Pfloat)random_real(width_lo, width_hi));
    pset_linetype(linetype);
    pset_anno_char_ht(0.02f);
    pset_anno_style(style);
    panno_text_rel(&l.ref, &l.offset, "X");
    pclose_struct();
    return l;
}

static void lead_lines(void) {
    for (int round = 0; round < 8; ++round) {
        const Pint style = round % 2 ? PANNO_STYLE_LEAD_LINE : PANNO_STYLE_UNCONNECTED + 2 * (round % 4 == 2);
        const int lead = style == PANNO_STYLE_LEAD_LINE;
        const Lead l = lead_structure(style, PLINE_SOLID, 2.0, 4.0);
        Picture p[2];
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int i = 0; i < 2; ++i) {
            if (!p[i].rgb) continue;
            for (int k = 1; k <= 4; ++k) {
                const double t = 0.15 * k, x = l.ref.x + t * l.offset.delta_x,
                             y = l.ref.y + t * l.offset.delta_y;
                const int shows = colour_near(&p[i], x, y, l.rgb);
                if (shows != lead)
                    fprintf(stderr, "  %s, style %d: at NPC (%.3f, %.3f) the line %s\n", p[i].name,
                            (int)style, x, y, shows ? "shows" : "is missing");
                CHECK(shows == lead);
            }
            free(p[i].rgb);
        }
    }
}

/* A patterned lead line: of 80 points along its way, clear of the text, some show its colour and
 * some (in the pattern's gaps, 6 or more pixels long) do not. */
static void patterned_lead_lines(void) {
    const Pint types[4] = {PLINE_DASH, PLINE_DOT, PLINE_DASH_DOT, PLINE_DASH};
    for (int round = 0; round < 4; ++round) {
        const Lead l = lead_structure(PANNO_STYLE_LEAD_LINE, types[round], 1.0, 3.0);
        Picture p[2];
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int i = 0; i < 2; ++i) {
            if (!p[i].rgb) continue;
            int shown = 0;
            for (int k = 0; k < 80; ++k) {
                const double t = 0.1 + 0.8 * k / 79.0;
                shown +=
                    colour_near(&p[i], l.ref.x + t * l.offset.delta_x, l.ref.y + t * l.offset.delta_y, l.rgb);
            }
            if (shown == 0 || shown == 80)
                fprintf(stderr, "  %s, linetype %d: %d of 80 points along the lead line show it\n", p[i].name,
                        (int)types[round], shown);
            CHECK(shown > 0 && shown < 80);
            free(p[i].rgb);
        }
    }
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    seed_random(0xbb67ae8584caa73bULL);
    files = picture_files(dir, "annotation_lead");
    snprintf(errors, sizeof errors, "%s/annotation_lead_errors.txt", dir);
    open_with_handler(errors);
    lead_lines();
    patterned_lead_lines();
    pclose_phigs();
    return finish("test_annotation_lead");
}
