/* Shared checks of the C binding's tests: plain C11, nothing but <phigs.h>. */
#ifndef PHIGS_C_TEST_CHECK_H
#define PHIGS_C_TEST_CHECK_H

#include <phigs.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures = 0;

#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (!(cond)) {                                                               \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                              \
        }                                                                            \
    } while (0)

/* A fixed 64-bit linear congruential sequence (its high bits): the same random members on every
 * run; a test seeds it once at the start of main. */
static unsigned long long random_state = 1;

static inline void seed_random(unsigned long long seed) {
    random_state = seed;
}

static inline unsigned next_random(void) {
    random_state = random_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (unsigned)(random_state >> 33);
}

/* A random number in [lo, hi] from the same sequence (100,001 steps). */
static inline double random_real(double lo, double hi) {
    return lo + (hi - lo) * (next_random() % 100001u) / 100000.0;
}

/* A random axis-aligned square in z = 0 with its lower left corner in [0.2, 0.4]^2 and its side in
 * [0.2, 0.4] (given back in x0, y0, side), wound counter-clockwise seen from +z (front facing) or,
 * when backFacing, clockwise. */
static inline void random_square(Ppoint3 corners[4], int backFacing, double* x0, double* y0, double* side) {
    *x0 = random_real(0.2, 0.4), *y0 = random_real(0.2, 0.4), *side = random_real(0.2, 0.4);
    corners[0].x = (Pfloat)*x0, corners[0].y = (Pfloat)*y0;
    corners[1].x = (Pfloat)(*x0 + *side), corners[1].y = (Pfloat)*y0;
    corners[2].x = (Pfloat)(*x0 + *side), corners[2].y = (Pfloat)(*y0 + *side);
    corners[3].x = (Pfloat)*x0, corners[3].y = (Pfloat)(*y0 + *side);
    for (int k = 0; k < 4; ++k) corners[k].z = 0;
    if (backFacing) {
        const Ppoint3 t = corners[1];
        corners[1] = corners[3], corners[3] = t;
    }
}

/* Every call of the error handler, in order; each is passed on to perr_hand (the error file). */
#define MAX_ERRORS 32
static Pint error_numbers[MAX_ERRORS];
static Pint error_functions[MAX_ERRORS];
static int error_count = 0;

static inline void recording_handler(Pint err, Pint fn, const char* file) {
    if (error_count < MAX_ERRORS) {
        error_numbers[error_count] = err;
        error_functions[error_count] = fn;
    }
    ++error_count;
    perr_hand(err, fn, file);
}

/* The call reports exactly error `num` of function `fn` through the handler. */
#define EXPECT_ERROR(call, num, fn)                                                       \
    do {                                                                                  \
        error_count = 0;                                                                  \
        call;                                                                             \
        CHECK(error_count == 1);                                                          \
        if (error_count == 1) {                                                           \
            if (error_numbers[0] != (num) || error_functions[0] != (fn))                  \
                fprintf(stderr, "  got error %d of function %d\n", (int)error_numbers[0], \
                        (int)error_functions[0]);                                         \
            CHECK(error_numbers[0] == (num));                                             \
            CHECK(error_functions[0] == (fn));                                            \
        }                                                                                 \
    } while (0)

#define EXPECT_NO_ERROR(call)                                                                    \
    do {                                                                                         \
        error_count = 0;                                                                         \
        call;                                                                                    \
        if (error_count != 0) fprintf(stderr, "  unexpected error %d\n", (int)error_numbers[0]); \
        CHECK(error_count == 0);                                                                 \
    } while (0)

/* What the CSS holds, to show that a refused call changed nothing. */
#define SNAP_MAX 32
typedef struct {
    Pint ids[SNAP_MAX];
    Pint count;
    Pelem_type types[SNAP_MAX][SNAP_MAX];
    Pint lengths[SNAP_MAX];
    Popen_struct_status open_status;
    Pint open_id;
    Pint pointer;
} Snapshot;

static inline void snapshot(Snapshot* s) {
    Pint err = 0, total = 0;
    Pint_list ids;
    memset(s, 0, sizeof *s);
    ids.ints = s->ids;
    pinq_struct_ids(SNAP_MAX, 0, &err, &ids, &total);
    s->count = err == 0 ? ids.num_ints : -1;
    for (Pint i = 0; i < s->count; ++i) {
        for (Pint n = 1; n < SNAP_MAX; ++n) {
            size_t size = 0;
            pinq_elem_type_size(s->ids[i], n, &err, &s->types[i][n], &size);
            if (err != 0) break;
            s->lengths[i] = n;
        }
    }
    pinq_open_struct(&err, &s->open_status, &s->open_id);
    s->pointer = -1;
    if (s->open_status == PSTRUCT_OPEN) pinq_elem_ptr(&err, &s->pointer);
}

static inline int same_snapshot(const Snapshot* a, const Snapshot* b) {
    return memcmp(a, b, sizeof *a) == 0;
}

/* The call reports error `num` of `fn` and leaves the CSS as it was. */
#define EXPECT_REFUSED(call, num, fn)            \
    do {                                         \
        Snapshot before_, after_;                \
        snapshot(&before_);                      \
        EXPECT_ERROR(call, num, fn);             \
        snapshot(&after_);                       \
        CHECK(same_snapshot(&before_, &after_)); \
    } while (0)

/* A line of the file that is `line`, or `line` followed by the reason the core gave (" (...)"). */
static inline int file_has_line(const char* path, const char* line) {
    char buffer[2048];
    const size_t length = strlen(line);
    int found = 0;
    FILE* f = fopen(path, "r");
    if (!f) return 0;
    while (!found && fgets(buffer, sizeof buffer, f)) {
        buffer[strcspn(buffer, "\n")] = '\0';
        found = strncmp(buffer, line, length) == 0 &&
                (buffer[length] == '\0' || strncmp(buffer + length, " (", 2) == 0);
    }
    fclose(f);
    return found;
}

static inline int file_line_count(const char* path) {
    int lines = 0, c;
    FILE* f = fopen(path, "r");
    if (!f) return -1;
    while ((c = fgetc(f)) != EOF) lines += c == '\n';
    fclose(f);
    return lines;
}

/* Opens PHIGS with `file` as the error file and the recording handler. */
static inline void open_with_handler(const char* file) {
    void (*old)(Pint, Pint, const char*) = NULL;
    pset_err_hand(recording_handler, &old);
    popen_phigs(file, PDEF_MEM_SIZE);
}

static inline int finish(const char* name) {
    if (failures)
        fprintf(stderr, "%s: %d checks failed\n", name, failures);
    else
        printf("%s: all checks passed\n", name);
    return failures ? 1 : 0;
}

static inline int near(double a, double b) {
    return fabs(a - b) <= 1e-5 * (1.0 + fabs(b));
}

#endif
