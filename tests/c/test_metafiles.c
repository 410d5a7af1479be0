/* The metafile functions answer the standard's errors (no metafile workstation type: 56 for
 * output, 58 for input, 304 for INTERPRET ITEM), and INQUIRE TEXT EXTENT measures the Hershey
 * stroke fonts the workstations draw with. */
#include "check.h"

static void metafiles(const char* pdf) {
    Pitem_data data;
    Pint type = -1, length = -1;
    memset(&data, 0, sizeof data);
    EXPECT_ERROR(pwrite_item(1, 1, 0, &data), 3, Pfn_write_item);
    EXPECT_ERROR(pget_item_type(1, &type, &length), 3, Pfn_get_item_type);
    EXPECT_ERROR(pread_item(1, 10, &data), 3, Pfn_read_item);
    popen_ws(1, pdf, PWST_PDF);
    EXPECT_ERROR(pwrite_item(2, 1, 0, &data), 54, Pfn_write_item);
    EXPECT_ERROR(pwrite_item(1, 1, 0, &data), 56, Pfn_write_item);
    EXPECT_ERROR(pget_item_type(1, &type, &length), 58, Pfn_get_item_type);
    EXPECT_ERROR(pread_item(1, 10, &data), 58, Pfn_read_item);
    EXPECT_ERROR(pinterpret_item(1, 0, &data), 304, Pfn_interpret_item);
    EXPECT_ERROR(pinterpret_item(1, -1, &data), 301, Pfn_interpret_item);
    pclose_ws(1);
}

typedef struct {
    Prect rect;
    Ppoint concat;
    Pint err;
} Extent;

static Extent extent(Pint font, Pfloat expan, Pfloat space, Pfloat height, Ptext_path path,
                     Phor_text_align hor, Pvert_text_align vert, const char* s) {
    Extent e;
    memset(&e, 0, sizeof e);
    e.err = -1;
    pinq_text_extent(PWST_PDF, font, expan, space, height, path, hor, vert, s, &e.err, &e.rect, &e.concat);
    return e;
}

static void text_extent(void) {
    const Extent a = extent(1, 1, 0, 1, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "A");
    const Extent aa = extent(1, 1, 0, 1, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "AA");
    const double w = a.rect.q.x;
    CHECK(a.err == 0 && aa.err == 0);
    CHECK(w > 0.5 && w < 1.5);
    /* NORMAL is LEFT, BASE for path RIGHT: the body box from the baseline's start. */
    CHECK(near(a.rect.p.x, 0) && near(a.rect.p.y, -7.0 / 21) && near(a.rect.q.y, 25.0 / 21));
    CHECK(near(a.concat.x, w) && near(a.concat.y, 0));
    CHECK(near(aa.rect.q.x, 2 * w) && near(aa.concat.x, 2 * w));
    /* Spacing adds between characters (and before the next one), expansion widens, height scales. */
    const Extent spaced = extent(1, 1, 0.5f, 1, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "AA");
    CHECK(near(spaced.rect.q.x, 2 * w + 0.5) && near(spaced.concat.x, 2 * w + 1.0));
    CHECK(near(extent(1, 2, 0, 1, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "A").rect.q.x, 2 * w));
    const Extent tall = extent(1, 1, 0, 2, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "A");
    CHECK(near(tall.rect.q.x, 2 * w) && near(tall.rect.q.y, 50.0 / 21));
    /* Alignment moves the box: centre/half, right/top. */
    const Extent centred = extent(1, 1, 0, 1, PPATH_RIGHT, PHOR_CTR, PVERT_HALF, "AA");
    CHECK(near(centred.rect.p.x, -w) && near(centred.rect.q.x, w) && near(centred.rect.p.y, -0.5 - 7.0 / 21));
    const Extent top = extent(1, 1, 0, 1, PPATH_RIGHT, PHOR_RIGHT, PVERT_TOP, "A");
    CHECK(near(top.rect.q.x, 0) && near(top.rect.q.y, 0) && near(top.concat.x, 0));
    /* Path LEFT grows to negative x (NORMAL is RIGHT); path UP stacks cells of 32/21. */
    const Extent left = extent(1, 1, 0, 1, PPATH_LEFT, PHOR_NORM, PVERT_NORM, "AA");
    CHECK(near(left.rect.q.x, 0) && near(left.rect.p.x, -2 * w) && near(left.concat.x, -2 * w));
    const Extent up = extent(1, 1, 0, 1, PPATH_UP, PHOR_NORM, PVERT_NORM, "AA");
    CHECK(near(up.rect.p.x, -0.5 * w) && near(up.rect.q.x, 0.5 * w) && near(up.concat.y, 64.0 / 21));
    /* Fonts 1 to 4 differ; errors in *err_ind. */
    CHECK(extent(2, 1, 0, 1, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "AAAA").err == 0);
    CHECK(extent(5, 1, 0, 1, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "A").err == 106);
    /* A height, expansion or spacing that is not a number is refused (it answered NaN, error 0). */
    CHECK(extent(1, 1, 0, (Pfloat)NAN, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "A").err == -208);
    CHECK(extent(1, (Pfloat)INFINITY, 0, 1, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "A").err == -208);
    CHECK(extent(1, 1, (Pfloat)-INFINITY, 1, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "A").err == -208);
    CHECK(extent(1, 1, 0, 1, (Ptext_path)9, PHOR_NORM, PVERT_NORM, "A").err == PE_ENUM_TYPE_INVAL);
    CHECK(extent(1, 1, 0, 1, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, NULL).err == -204);
    {
        Prect r;
        Ppoint c;
        Pint err = -1;
        pinq_text_extent(99, 1, 1, 0, 1, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "A", &err, &r, &c);
        CHECK(err == 52);
    }
}

/* Random strings, fonts, paths, alignments, expansions and spacings (negative too): the extent
 * rectangle holds every character's body (an inverted or short box came of a negative spacing),
 * and the concatenation point stays on the alignment line, so a second string aligned alike
 * continues the first's line (path RIGHT or LEFT) or column (UP or DOWN): it drifted by the
 * alignment shift. With NORMAL alignment and spacing of 0 or more, "AB" measures as "A" then "B"
 * at the concatenation point. */
static void text_extent_classes(void) {
    static const char letters[] = "ilWAMBx1.";
    int inverted = 0, drifted = 0, short_box = 0, split = 0;
    seed_random(20261206);
    for (int round = 0; round < 400; ++round) {
        char text[8];
        const int n = 1 + (int)(next_random() % 6u);
        for (int i = 0; i < n; ++i) text[i] = letters[next_random() % (sizeof letters - 1)];
        text[n] = 0;
        const Pint font = 1 + (Pint)(next_random() % 4u);
        const Ptext_path path = (Ptext_path)(next_random() % 4u);
        const Phor_text_align hor = (Phor_text_align)(next_random() % 4u);
        const Pvert_text_align vert = (Pvert_text_align)(next_random() % 6u);
        const Pfloat expan = (Pfloat)random_real(0.3, 2.0), space = (Pfloat)random_real(-1.5, 1.0);
        const Pfloat height = (Pfloat)random_real(0.1, 3.0);
        const Extent e = extent(font, expan, space, height, path, hor, vert, text);
        CHECK(e.err == 0);
        inverted += e.rect.p.x > e.rect.q.x || e.rect.p.y > e.rect.q.y;
        drifted += path == PPATH_RIGHT || path == PPATH_LEFT ? !near(e.concat.y, 0) : !near(e.concat.x, 0);
        for (int i = 0; i < n; ++i) {
            /* Each character's body is as wide (path RIGHT, LEFT) or tall (UP, DOWN) alone. */
            char one[2] = {text[i], 0};
            const Extent c = extent(font, expan, space, height, path, hor, vert, one);
            const int across = path == PPATH_RIGHT || path == PPATH_LEFT;
            const double whole = across ? e.rect.q.x - e.rect.p.x : e.rect.q.y - e.rect.p.y;
            const double part = across ? c.rect.q.x - c.rect.p.x : c.rect.q.y - c.rect.p.y;
            short_box += whole < part - 1e-4;
        }
        /* (With negative spacing a character may reach back past the string's start, and the
         * alignment then moves the whole string: it does not split.) */
        if (n >= 2 && space >= 0 && (path == PPATH_RIGHT || path == PPATH_LEFT)) {
            char head[2] = {text[0], 0};
            const Extent first = extent(font, expan, space, height, path, PHOR_NORM, PVERT_NORM, head);
            const Extent rest = extent(font, expan, space, height, path, PHOR_NORM, PVERT_NORM, text + 1);
            const Extent all = extent(font, expan, space, height, path, PHOR_NORM, PVERT_NORM, text);
            const double lo = fmin(first.rect.p.x, first.concat.x + rest.rect.p.x);
            const double hi = fmax(first.rect.q.x, first.concat.x + rest.rect.q.x);
            split += !near(all.rect.p.x, lo) || !near(all.rect.q.x, hi) ||
                     !near(all.concat.x, first.concat.x + rest.concat.x);
        }
    }
    CHECK(inverted == 0);
    CHECK(drifted == 0);
    CHECK(short_box == 0);
    CHECK(split == 0);
    if (inverted || drifted || short_box || split)
        fprintf(
            stderr,
            "  text extent: %d inverted, %d concatenation points off the line, %d short boxes, %d split\n",
            inverted, drifted, short_box, split);
}

int main(int argc, char** argv) {
    char file[512], pdf[512];
    const char* dir = argc > 1 ? argv[1] : ".";
    snprintf(file, sizeof file, "%s/metafiles_errors.txt", dir);
    snprintf(pdf, sizeof pdf, "%s/metafiles.pdf", dir);
    CHECK(extent(1, 1, 0, 1, PPATH_RIGHT, PHOR_NORM, PVERT_NORM, "A").err == 2);
    open_with_handler(file);
    metafiles(pdf);
    error_count = 0;
    text_extent();
    text_extent_classes();
    CHECK(error_count == 0);
    pclose_phigs();
    return finish("test_metafiles");
}
