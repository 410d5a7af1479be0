/* phigs.h spells what old programs use as the binding spells it: the error numbers and function
 * identifiers are macros (#ifdef finds them; NIST's PHIGS validation test 11.02/01 checks them
 * so), a general colour's components are val.general, a vertex colour's direct is a Pcolr_rep,
 * popen_ws takes and pinq_ws_conn_type answers the connection identifier as a void pointer. The errors the
 * library raises carry the numbers the macros name. argv[1]: a directory for the files. */
#include "check.h"

#include <stdio.h>
#include <string.h>

/* Preprocessor checks: a missing or wrong macro fails the build of this test. */
#if !defined(Pfn_open_phigs) || Pfn_open_phigs != 0 || !defined(Pfn_set_elem_ptr_label) || \
    Pfn_set_elem_ptr_label != 100 || !defined(Pfn_del_elems_labels) || Pfn_del_elems_labels != 103
#error "the ISO function identifiers are not the binding's macros"
#endif
#if !defined(PE_NO_ERROR) || PE_NO_ERROR != 0 || !defined(PE_NOT_STOP) || PE_NOT_STOP != 5 || \
    !defined(PE_BAD_WS_TYPE) || PE_BAD_WS_TYPE != 52 || !defined(PE_REP_UNDEF) || PE_REP_UNDEF != 101
#error "the workstation and state error numbers are not the binding's macros"
#endif
#if !defined(PE_BAD_VUP_VPN) || PE_BAD_VUP_VPN != 161 || !defined(PE_BAD_STRUCT) || PE_BAD_STRUCT != 201 || \
    !defined(PE_NO_LABEL) || PE_NO_LABEL != 205 || !defined(PE_BAD_DISP_PRI) || PE_BAD_DISP_PRI != 208
#error "the viewing and structure error numbers are not the binding's macros"
#endif
#if !defined(Pfn_set_err_hand) || Pfn_set_err_hand != 181 || !defined(PE_BAD_INT_SHADE) ||    \
    PE_BAD_INT_SHADE != 123 || !defined(PE_BAD_COLR_RANGE) || PE_BAD_COLR_RANGE != 136 ||     \
    !defined(PLOC_DIGIT) || PLOC_DIGIT != 6 || !defined(PSTROKE_LINE) || PSTROKE_LINE != 4 || \
    !defined(PCHOICE_STRUCT) || PCHOICE_STRUCT != 5 || !defined(PPICK_STRUCT_NETWORK) ||      \
    PPICK_STRUCT_NETWORK != 3
#error "the PHIGS PLUS error numbers, error handling identifier or prompt/echo types are missing"
#endif
#if !defined(PE_NOT_REQUEST) || PE_NOT_REQUEST != 251 || !defined(PE_NAME_CONFLICT) ||            \
    PE_NAME_CONFLICT != 405 || !defined(PE_AR_NO_STRUCT_EMPTY) || PE_AR_NO_STRUCT_EMPTY != 408 || \
    !defined(PE_BAD_ERROR_FILE) || PE_BAD_ERROR_FILE != 450 || !defined(PE_BAD_KNOTS) ||          \
    PE_BAD_KNOTS != 503 || !defined(PE_ARITHMETIC_ERROR) || PE_ARITHMETIC_ERROR != 908 ||         \
    !defined(PE_LIST_LENGTH_LT_ZERO) || PE_LIST_LENGTH_LT_ZERO != 2201
#error "the input, archive, PHIGS PLUS and system error numbers are not the binding's macros"
#endif

/* Raised errors carry the numbers the macros name. */
static void errors_by_name(void) {
    Pint labels[1] = {1};
    Pint_list names = {1, labels};
    EXPECT_ERROR(ppolyline(NULL), PE_NOT_STOP, Pfn_polyline);
    EXPECT_ERROR(pset_elem_ptr_label(7), PE_NOT_STOP, Pfn_set_elem_ptr_label);
    EXPECT_NO_ERROR(popen_struct(1));
    EXPECT_ERROR(pset_elem_ptr_label(7), PE_NO_LABEL, Pfn_set_elem_ptr_label);
    EXPECT_ERROR(pdel_elems_labels(1, 2), PE_NO_LABELS, Pfn_del_elems_labels);
    EXPECT_NO_ERROR(padd_names_set(&names));
    EXPECT_NO_ERROR(pclose_struct());
    EXPECT_ERROR(ppost_struct(1, 1, 0.5f), PE_NOT_WSOP, Pfn_post_struct); /* no workstation open */
}

/* The colour records as the binding spells them, read back through an element's content. */
static void colour_members(void) {
    Pgcolr colr;
    Pint err = 0;
    Pelem_data* data = NULL;
    Pstore store = NULL;
    Pptco3 vertices[2];
    Pline_vdata_list3 vdata;
    colr.type = PMODEL_RGB;
    colr.val.general.x = 1.0f, colr.val.general.y = 0.25f, colr.val.general.z = 0.0f;
    memset(vertices, 0, sizeof vertices);
    vertices[1].point.x = 1.0f;
    vertices[0].colr.direct.rgb.red = 0.5f, vertices[1].colr.direct.hsv.value = 0.75f;
    vdata.num_vertices = 2;
    vdata.vertex_data.ptcolrs = vertices;
    EXPECT_NO_ERROR(popen_struct(2));
    EXPECT_NO_ERROR(pset_line_colr(&colr));
    EXPECT_NO_ERROR(ppolyline_set3_data(PVERT_COORD_COLOUR, PMODEL_RGB, 1, &vdata));
    EXPECT_NO_ERROR(pclose_struct());
    pcreate_store(&err, &store);
    CHECK(err == 0);
    pinq_elem_content(2, 1, store, &err, &data);
    CHECK(err == 0 && data && data->colr.type == PMODEL_RGB && data->colr.val.general.y == 0.25f);
    pinq_elem_content(2, 2, store, &err, &data);
    CHECK(err == 0 && data);
    if (err == 0 && data) {
        const Pptco3* read = data->plsd3.vdata->vertex_data.ptcolrs;
        /* Every member of Pcolr_rep holds the same three components. */
        CHECK(read[0].colr.direct.rgb.red == 0.5f && read[0].colr.direct.hsv.hue == 0.5f);
        CHECK(read[1].colr.direct.rgb.blue == 0.75f);
    }
    pdel_store(store);
}

/* pinq_ws_conn_type answers the connection identifier through a void ** (a char string here). */
static void connection(const char* dir) {
    char file[512];
    void* conn = NULL;
    Pint err = 0, type = 0;
    Pstore store = NULL;
    void* id = file; /* old programs pass a connection identifier of their own type */
    snprintf(file, sizeof file, "%s/standard_names.svg", dir);
    EXPECT_NO_ERROR(popen_ws(1, id, PWST_SVG));
    pcreate_store(&err, &store);
    pinq_ws_conn_type(1, store, &err, &conn, &type);
    CHECK(err == PE_NO_ERROR && conn && strcmp((const char*)conn, file) == 0 && type >= PWST_SPECIFIC_BASE);
    pinq_ws_conn_type(2, store, &err, &conn, &type);
    CHECK(err == PE_WS_NOT_OPEN);
    pdel_store(store);
    EXPECT_NO_ERROR(pclose_ws(1));
}

int main(int argc, char** argv) {
    char errors[512];
    const char* dir = argc > 1 ? argv[1] : ".";
    snprintf(errors, sizeof errors, "%s/standard_names_errors.txt", dir);
    popen_phigs(errors, PDEF_MEM_SIZE);
    pset_err_hand(recording_handler, NULL);
    errors_by_name();
    colour_members();
    connection(dir);
    pclose_phigs();
    if (failures) fprintf(stderr, "%d checks failed\n", failures);
    return failures ? 1 : 0;
}
