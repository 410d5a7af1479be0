/* The window workstation shows each change at once under ASAP, with no UPDATE or input call after
 * it; it keeps its picture while the program waits for input (label window,
 * under an Xvfb of its own): a window put over it and taken away again, or a resize, is repainted
 * during AWAIT EVENT, which goes on to its timeout rather than ending early with NONE; text typed
 * into string device 1 (echo on, prompt/echo type 1) shows in its echo area; a choice device with
 * a menu (prompt/echo type 3) in EVENT mode with echo on shows its panel, the alternative clicked
 * highlighted, until it leaves EVENT mode. The window's pixels
 * are read back and keys typed through Xlib and XTest (the test, not the binding, uses X). */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XTest.h>
#include <X11/keysym.h>
#include <time.h>

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The top-level window named `name` (GLFW sets WM_NAME), or 0. */
static Window find_named(Display* x, Window from, const char* name) {
    char* title = NULL;
    if (XFetchName(x, from, &title) && title) {
        const int same = strcmp(title, name) == 0;
        XFree(title);
        if (same) return from;
    }
    Window root, parent, *children = NULL;
    unsigned count = 0;
    Window found = 0;
    if (XQueryTree(x, from, &root, &parent, &children, &count)) {
        for (unsigned i = 0; i < count && !found; ++i) found = find_named(x, children[i], name);
        if (children) XFree(children);
    }
    return found;
}

/* Pixels of the window that are red (the square) and magenta (the cover), and whether the
 * pixel at (px, py) is red. */
static void count_colours(Display* x, Window w, int px, int py, int* red, int* magenta, int* red_at) {
    XWindowAttributes a;
    XGetWindowAttributes(x, w, &a);
    XImage* image = XGetImage(x, w, 0, 0, (unsigned)a.width, (unsigned)a.height, AllPlanes, ZPixmap);
    *red = *magenta = *red_at = 0;
    if (!image) return;
    for (int j = 0; j < a.height; ++j)
        for (int i = 0; i < a.width; ++i) {
            const unsigned long p = XGetPixel(image, i, j);
            const unsigned r = (unsigned)(p >> 16) & 255u, g = (unsigned)(p >> 8) & 255u,
                           b = (unsigned)p & 255u;
            const int is_red = r > 200 && g < 60 && b < 60;
            *red += is_red;
            *magenta += r > 200 && g < 60 && b > 200;
            if (i == px && j == py) *red_at = is_red;
        }
    XDestroyImage(image);
}

/* Pixels of the string echo's box colour (EchoStyle::box, 0.22 0.24 0.30) in rows y0..y1. */
static int echo_box_pixels(Display* x, Window w, int y0, int y1) {
    XWindowAttributes a;
    XGetWindowAttributes(x, w, &a);
    XImage* image = XGetImage(x, w, 0, 0, (unsigned)a.width, (unsigned)a.height, AllPlanes, ZPixmap);
    int n = 0;
    if (!image) return 0;
    for (int j = y0; j <= y1 && j < a.height; ++j)
        for (int i = 0; i < a.width; ++i) {
            const unsigned long p = XGetPixel(image, i, j);
            const int r = (int)(p >> 16) & 255, g = (int)(p >> 8) & 255, b = (int)p & 255;
            n += abs(r - 56) < 12 && abs(g - 61) < 12 && abs(b - 77) < 12;
        }
    XDestroyImage(image);
    return n;
}

/* Pixels within (x0, y0)..(x1, y1) (window pixels, y down) within 12 of the colour r, g, b. */
static int colour_pixels(Display* x, Window w, int x0, int y0, int x1, int y1, int r, int g, int b) {
    XWindowAttributes a;
    XGetWindowAttributes(x, w, &a);
    XImage* image = XGetImage(x, w, 0, 0, (unsigned)a.width, (unsigned)a.height, AllPlanes, ZPixmap);
    int n = 0;
    if (!image) return 0;
    for (int j = y0 < 0 ? 0 : y0; j <= y1 && j < a.height; ++j)
        for (int i = x0 < 0 ? 0 : x0; i <= x1 && i < a.width; ++i) {
            const unsigned long p = XGetPixel(image, i, j);
            const int pr = (int)(p >> 16) & 255, pg = (int)(p >> 8) & 255, pb = (int)p & 255;
            n += abs(pr - r) < 12 && abs(pg - g) < 12 && abs(pb - b) < 12;
        }
    XDestroyImage(image);
    return n;
}

/* Sleeps `seconds` without calling PHIGS, as an old program waiting on the operator does. */
static void sleep_without_phigs(double seconds) {
    struct timespec t = {(time_t)seconds, (long)((seconds - (double)(time_t)seconds) * 1e9)};
    nanosleep(&t, NULL);
}

/* Under ASAP (the default) windows show each change at once, with no UPDATE WORKSTATION and no
 * input call after it: random steps on two windows (a square of a new colour added to a posted
 * structure, some while the structure stays open, one structure unposted, a colour changed
 * through the colour table), each followed by a wait in which the program calls nothing; each
 * window then shows exactly the colours the posted squares have. */
static void asap_without_update(Display* x) {
    enum { kSquares = 6 };
    /* Twelve colours apart from each other and from the black background: square k shows
     * palette[k], or palette[k + 6] after its colour changed an odd number of times. */
    static const float palette[12][3] = {{1, 0, 0},    {0, 1, 0}, {0, 0, 1},          {1, 1, 0},
                                         {0, 1, 1},    {1, 0, 1}, {1, 0.5f, 0},       {0.5f, 0, 1},
                                         {0, 0.5f, 0}, {1, 1, 1}, {0.5f, 0.5f, 0.5f}, {0, 0.5f, 1}};
    int posted[kSquares] = {0}, changed[kSquares] = {0};
    Pcolr_rep colours[kSquares];
    seed_random(20261207);
    /* Two windows: each is shown, not only the first found behind. */
    EXPECT_NO_ERROR(popen_ws(2, NULL, PWST_WINDOW));
    EXPECT_NO_ERROR(popen_ws(3, NULL, PWST_WINDOW));
    for (int k = 0; k < kSquares; ++k)
        colours[k].rgb.red = palette[k][0], colours[k].rgb.green = palette[k][1],
        colours[k].rgb.blue = palette[k][2];
    /* Side by side (both open at the same place, the second over the first). */
    Window windows[2] = {0, 0};
    sleep_without_phigs(0.3);
    for (int v = 0; v < 2; ++v) {
        windows[v] =
            find_named(x, DefaultRootWindow(x), v == 0 ? "PHIGS workstation 2" : "PHIGS workstation 3");
        CHECK(windows[v] != 0);
        if (windows[v]) XMoveResizeWindow(x, windows[v], 640 * v, 0, 560, 420);
    }
    XSync(x, False);
    for (int step = 0; step < 12 && windows[0] && windows[1]; ++step) {
        const int k = (int)(next_random() % kSquares);
        const int building = step % 4 == 3; /* the structure stays open while the program waits */
        if (!posted[k] && step % 3 != 2) {
            const float x0 = 0.05f + 0.15f * (float)k;
            Ppoint points[4] = {{x0, 0.3f}, {x0 + 0.1f, 0.3f}, {x0 + 0.1f, 0.7f}, {x0, 0.7f}};
            Ppoint_list square = {4, points};
            for (Pint ws = 2; ws <= 3; ++ws) {
                EXPECT_NO_ERROR(pset_colr_rep(ws, 10 + k, &colours[k]));
                EXPECT_NO_ERROR(ppost_struct(ws, 100 + k, 0.5f));
            }
            EXPECT_NO_ERROR(popen_struct(100 + k));
            EXPECT_NO_ERROR(pempty_struct(100 + k));
            EXPECT_NO_ERROR(pset_int_style(PSTYLE_SOLID));
            EXPECT_NO_ERROR(pset_int_colr_ind(10 + k));
            if (building) sleep_without_phigs(0.15); /* past the building interval */
            EXPECT_NO_ERROR(pfill_area(&square));
            if (!building) EXPECT_NO_ERROR(pclose_struct());
            posted[k] = 1;
        } else if (posted[k] && step % 3 != 2) {
            for (Pint ws = 2; ws <= 3; ++ws) EXPECT_NO_ERROR(punpost_struct(ws, 100 + k));
            posted[k] = 0;
        } else {
            changed[k] = !changed[k];
            const float* c = palette[k + (changed[k] ? kSquares : 0)];
            colours[k].rgb.red = c[0], colours[k].rgb.green = c[1], colours[k].rgb.blue = c[2];
            for (Pint ws = 2; ws <= 3; ++ws) EXPECT_NO_ERROR(pset_colr_rep(ws, 10 + k, &colours[k]));
        }
        sleep_without_phigs(0.4);
        for (int v = 0; v < 2; ++v) {
            if (!windows[v])
                windows[v] = find_named(x, DefaultRootWindow(x),
                                        v == 0 ? "PHIGS workstation 2" : "PHIGS workstation 3");
            CHECK(windows[v] != 0);
            if (!windows[v]) continue;
            for (int j = 0; j < kSquares; ++j) {
                const int r = (int)(255 * colours[j].rgb.red + 0.5f),
                          g = (int)(255 * colours[j].rgb.green + 0.5f),
                          b = (int)(255 * colours[j].rgb.blue + 0.5f);
                const int shown = colour_pixels(x, windows[v], 0, 0, 4096, 4096, r, g, b) > 500;
                if (shown != posted[j])
                    fprintf(stderr, "  step %d, window %d: square %d shown %d, posted %d\n", step, v + 2, j,
                            shown, posted[j]);
                CHECK(shown == posted[j]);
            }
        }
        Popen_struct_status open = PSTRUCT_NONE;
        Pint err = 0, id = 0;
        pinq_open_struct(&err, &open, &id);
        if (open == PSTRUCT_OPEN) EXPECT_NO_ERROR(pclose_struct());
    }
    EXPECT_NO_ERROR(pclose_ws(2));
    EXPECT_NO_ERROR(pclose_ws(3));
}

static void type_key(Display* x, KeySym key) {
    const KeyCode code = XKeysymToKeycode(x, key);
    XTestFakeKeyEvent(x, code, True, 0);
    XTestFakeKeyEvent(x, code, False, 0);
    XSync(x, False);
}

/* AWAIT EVENT for `seconds` with no operator: NONE, and only at the timeout. */
static void await_whole_timeout(float seconds) {
    Pint ws = -1, number = -1;
    Pin_class in_class = PIN_LOC;
    const double start = now();
    EXPECT_NO_ERROR(pawait_event(seconds, &ws, &in_class, &number));
    CHECK(in_class == PIN_NONE);
    CHECK(now() - start >= 0.9 * seconds);
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    snprintf(errors, sizeof errors, "%s/window_repaint_errors.txt", dir);
    Display* x = XOpenDisplay(NULL);
    CHECK(x != NULL);
    if (!x) return finish("window_repaint");
    open_with_handler(errors);
    Ppoint points[4] = {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.9f, 0.9f}, {0.1f, 0.9f}};
    Ppoint_list square = {4, points};
    Pgcolr red = {PMODEL_RGB, {0}};
    red.val.general.x = 1;
    popen_struct(1);
    pset_int_style(PSTYLE_SOLID);
    pset_int_colr(&red);
    pfill_area(&square);
    pclose_struct();
    EXPECT_NO_ERROR(popen_ws(1, NULL, PWST_WINDOW));
    EXPECT_NO_ERROR(ppost_struct(1, 1, 0.5f));
    EXPECT_NO_ERROR(pupd_ws(1, PFLAG_PERFORM));
    EXPECT_NO_ERROR(pset_choice_mode(1, 1, POP_EVENT, PSWITCH_ECHO));
    await_whole_timeout(0.3f); /* the window is mapped and drawn */
    const Window w = find_named(x, DefaultRootWindow(x), "PHIGS workstation 1");
    CHECK(w != 0);
    if (!w) return finish("window_repaint");
    int reds = 0, magentas = 0, red_at = 0;
    count_colours(x, w, 0, 0, &reds, &magentas, &red_at);
    CHECK(reds > 1000 && magentas == 0);

    /* A magenta window over it, taken away again: the damage is repainted during the wait. */
    for (int round = 0; round < 3; ++round) {
        XWindowAttributes a;
        XGetWindowAttributes(x, w, &a);
        int wx = 0, wy = 0;
        Window child;
        XTranslateCoordinates(x, w, DefaultRootWindow(x), 0, 0, &wx, &wy, &child);
        XSetWindowAttributes cover_attributes;
        cover_attributes.override_redirect = True;
        cover_attributes.background_pixel = 0xff00ffUL;
        const Window cover =
            XCreateWindow(x, DefaultRootWindow(x), wx + 20 * round, wy + 10 * round, (unsigned)a.width / 2,
                          (unsigned)a.height / 2, 0, CopyFromParent, InputOutput, CopyFromParent,
                          CWOverrideRedirect | CWBackPixel, &cover_attributes);
        XMapRaised(x, cover);
        XSync(x, False);
        struct timespec pause = {0, 200000000};
        nanosleep(&pause, NULL);
        XDestroyWindow(x, cover);
        XSync(x, False);
        await_whole_timeout(0.4f);
        count_colours(x, w, 0, 0, &reds, &magentas, &red_at);
        CHECK(magentas == 0);
        CHECK(reds > 1000);
    }

    /* Typed text shows in the string echo area while the program waits; Enter gives the string. */
    {
        XWindowAttributes a;
        XGetWindowAttributes(x, w, &a);
        Plimit area = {100.0f, 500.0f, 100.0f, 150.0f}; /* DC, y up */
        Pstring_data data = {80, 1, {{0}}};
        EXPECT_NO_ERROR(pinit_string(1, 1, "", 1, &area, &data));
        EXPECT_NO_ERROR(pset_string_mode(1, 1, POP_EVENT, PSWITCH_ECHO));
        int wx = 0, wy = 0;
        Window child;
        XTranslateCoordinates(x, w, DefaultRootWindow(x), 0, 0, &wx, &wy, &child);
        XTestFakeMotionEvent(x, -1, wx + 300, wy + 300, 0); /* the keyboard goes to the window */
        XSync(x, False);
        await_whole_timeout(0.2f);
        const int top = a.height - 150, bottom = a.height - 100;
        CHECK(echo_box_pixels(x, w, top, bottom) == 0);
        type_key(x, XK_a);
        type_key(x, XK_b);
        type_key(x, XK_c);
        await_whole_timeout(0.3f);
        CHECK(echo_box_pixels(x, w, top, bottom) > 1000);
        CHECK(echo_box_pixels(x, w, 0, top - 10) == 0);
        type_key(x, XK_Return);
        Pint ws = -1, number = -1;
        Pin_class in_class = PIN_NONE;
        char typed[81] = {0};
        EXPECT_NO_ERROR(pawait_event(2.0f, &ws, &in_class, &number));
        CHECK(in_class == PIN_STRING);
        if (in_class == PIN_STRING) pget_string(typed);
        CHECK(strcmp(typed, "abc") == 0);
        EXPECT_NO_ERROR(pset_string_mode(1, 1, POP_REQ, PSWITCH_ECHO));
    }

    /* A menu panel (choice prompt/echo type 3) shows while the device is in EVENT mode with
     * echo on: three rows of 40 pixels, the current alternative in EchoStyle::current (0.95 0.70
     * 0.15), the others in EchoStyle::box; a click on the third chooses it and moves the
     * highlight there; back in REQUEST mode the panel is gone. */
    {
        XWindowAttributes a;
        XGetWindowAttributes(x, w, &a);
        Plimit area = {600.0f, 700.0f, 400.0f, 520.0f}; /* DC, y up */
        char* names[3] = {"wing", "tail", "body"};
        Pchoice_data menu;
        menu.pets.pet_r3.num_strings = 3;
        menu.pets.pet_r3.strings = names;
        EXPECT_NO_ERROR(pset_choice_mode(1, 1, POP_REQ, PSWITCH_ECHO));
        EXPECT_NO_ERROR(pinit_choice(1, 1, PIN_STATUS_OK, 1, 3, &area, &menu));
        const int top = a.height - 520;
        await_whole_timeout(0.2f);
        CHECK(colour_pixels(x, w, 600, top, 700, top + 120, 56, 61, 77) == 0);
        EXPECT_NO_ERROR(pset_choice_mode(1, 1, POP_EVENT, PSWITCH_ECHO));
        await_whole_timeout(0.3f);
        CHECK(colour_pixels(x, w, 600, top + 40, 700, top + 120, 56, 61, 77) > 4000);
        CHECK(colour_pixels(x, w, 600, top, 700, top + 40, 242, 178, 38) > 2000);
        int wx = 0, wy = 0;
        Window child;
        XTranslateCoordinates(x, w, DefaultRootWindow(x), 0, 0, &wx, &wy, &child);
        XTestFakeMotionEvent(x, -1, wx + 650, wy + top + 100, 0);
        XTestFakeButtonEvent(x, 1, True, 0);
        XTestFakeButtonEvent(x, 1, False, 0);
        XSync(x, False);
        Pint ws = -1, number = -1, choice = 0;
        Pin_class in_class = PIN_NONE;
        Pin_status status = PIN_STATUS_NONE;
        EXPECT_NO_ERROR(pawait_event(2.0f, &ws, &in_class, &number));
        CHECK(in_class == PIN_CHOICE);
        if (in_class == PIN_CHOICE) pget_choice(&status, &choice);
        CHECK(status == PIN_STATUS_OK && choice == 3);
        await_whole_timeout(0.3f);
        CHECK(colour_pixels(x, w, 600, top + 80, 700, top + 120, 242, 178, 38) > 2000);
        CHECK(colour_pixels(x, w, 600, top, 700, top + 40, 242, 178, 38) == 0);
        EXPECT_NO_ERROR(pset_choice_mode(1, 1, POP_REQ, PSWITCH_ECHO));
        await_whole_timeout(0.3f);
        CHECK(colour_pixels(x, w, 600, top, 700, top + 120, 56, 61, 77) == 0);
        CHECK(colour_pixels(x, w, 600, top, 700, top + 120, 242, 178, 38) == 0);
    }

    /* Resized: redrawn at the new size (the square's centre at the middle of the lower left
     * square of the window) while the program only waits. */
    const unsigned sizes[3][2] = {{600, 400}, {300, 500}, {900, 300}};
    for (int k = 0; k < 3; ++k) {
        XResizeWindow(x, w, sizes[k][0], sizes[k][1]);
        XSync(x, False);
        await_whole_timeout(0.5f);
        const int side = (int)(sizes[k][0] < sizes[k][1] ? sizes[k][0] : sizes[k][1]);
        count_colours(x, w, side / 2, (int)sizes[k][1] - side / 2, &reds, &magentas, &red_at);
        CHECK(red_at);
        CHECK(reds > side * side / 3);
    }
    pclose_ws(1);
    asap_without_update(x);
    pclose_phigs();
    XCloseDisplay(x);
    return finish("window_repaint");
}
