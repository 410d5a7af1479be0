/* Example 7, the C binding: the structure of example 1 (a yellow polyline and white text)
 * built through phigs.h alone, written to an archive file, the store emptied, the structure
 * retrieved from the archive and inquired element by element. (phigs.h has no workstation
 * functions yet, so this example stores and inquires where example 1 draws.)
 *
 *     hello_c [FILE]      the archive file (default: hello_c.phigs)
 */
#include <phigs.h>
#include <stdio.h>

static const char* element_name(Pelem_type type) {
    switch (type) {
        case PELEM_LINE_COLR:
            return "SET POLYLINE COLOUR";
        case PELEM_LINEWIDTH:
            return "SET LINEWIDTH SCALE FACTOR";
        case PELEM_POLYLINE3:
            return "POLYLINE 3";
        case PELEM_TEXT_COLR:
            return "SET TEXT COLOUR";
        case PELEM_CHAR_HT:
            return "SET CHARACTER HEIGHT";
        case PELEM_TEXT3:
            return "TEXT 3";
        default:
            return "other";
    }
}

int main(int argc, char** argv) {
    const char* file = argc > 1 ? argv[1] : "hello_c.phigs";
    Ppoint3 zigzag[5] = {{0.1f, 0.2f, 0}, {0.3f, 0.5f, 0}, {0.5f, 0.2f, 0}, {0.7f, 0.5f, 0}, {0.9f, 0.2f, 0}};
    Ppoint_list3 line = {5, zigzag};
    Ppoint3 text_position = {0.1f, 0.7f, 0};
    Pvec3 text_directions[2] = {{1, 0, 0}, {0, 1, 0}};
    Pgcolr yellow, white;
    Pint one = 1;
    Pint_list structures = {1, &one};
    Pint err = 0, n, element;
    Pstruct_status status;
    Pelem_type type;
    size_t size;

    yellow.type = PMODEL_RGB;
    yellow.val.direct.x = 1, yellow.val.direct.y = 1, yellow.val.direct.z = 0;
    white.type = PMODEL_RGB;
    white.val.direct.x = 1, white.val.direct.y = 1, white.val.direct.z = 1;

    popen_phigs(NULL, PDEF_MEM_SIZE); /* errors, if any, are written to stderr */
    popen_struct(1);
    pset_line_colr(&yellow);
    pset_linewidth(3);
    ppolyline3(&line);
    pset_text_colr(&white);
    pset_char_ht(0.08f);
    ptext3(&text_position, text_directions, "Hello, PHIGS");
    pclose_struct();

    /* ARCHIVE STRUCTURES, then DELETE ALL STRUCTURES: the store is empty. */
    popen_ar_file(1, file);
    par_structs(1, &structures);
    pdel_all_structs();
    pinq_struct_status(1, &err, &status);
    printf("after deleting: structure 1 %s\n",
           status == PSTRUCT_STATUS_NON_EXIST ? "does not exist" : "exists");

    /* RETRIEVE STRUCTURES brings it back from the file. */
    pret_structs(1, &structures);
    pclose_ar_file(1);
    pinq_struct_status(1, &err, &status);
    printf("after retrieving: structure 1 %s\n",
           status == PSTRUCT_STATUS_NOT_EMPTY ? "is back" : "is missing");
    n = 0;
    for (element = 1;; ++element) {
        pinq_elem_type_size(1, element, &err, &type, &size);
        if (err != 0) break; /* 202: no such element, the end of the structure */
        printf("  element %d: %s\n", (int)element, element_name(type));
        ++n;
    }
    printf("%d elements\n", (int)n);
    pclose_phigs();
    return n == 6 ? 0 : 1;
}
