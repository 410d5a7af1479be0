/* Structure creation, editing and manipulation, with the ISO 9592 cases the core follows:
 * element pointer positions, missing structures that are no error, and every refusal leaving
 * the CSS as it was. argv[1]: a directory for the error file. */
#include "check.h"

static Pint pointer(void) {
    Pint err = -1, value = -1;
    pinq_elem_ptr(&err, &value);
    return err == 0 ? value : -100 - err;
}

static Pstruct_status status_of(Pint id) {
    Pint err = -1;
    Pstruct_status status = PSTRUCT_STATUS_NON_EXIST;
    pinq_struct_status(id, &err, &status);
    CHECK(err == 0);
    return status;
}

static Pint label_at(Pint id, Pint n, Pstore store) {
    Pint err = -1;
    Pelem_data* data = NULL;
    pinq_elem_content(id, n, store, &err, &data);
    return err == 0 && data ? data->int_data : -1;
}

static void labels(Pint id, Pint from, Pint to) {
    popen_struct(id);
    for (Pint l = from; l <= to; ++l) plabel(l);
    pclose_struct();
}

static void pointer_moves(Pstore store) {
    labels(1, 1, 5);
    EXPECT_NO_ERROR(popen_struct(1));
    CHECK(pointer() == 5);
    pset_elem_ptr(2);
    CHECK(pointer() == 2);
    pset_elem_ptr(-3);
    CHECK(pointer() == 0);
    pset_elem_ptr(99);
    CHECK(pointer() == 5);
    poffset_elem_ptr(-2);
    CHECK(pointer() == 3);
    poffset_elem_ptr(10);
    CHECK(pointer() == 5);
    pset_elem_ptr(0);
    pset_elem_ptr_label(3);
    CHECK(pointer() == 3);
    EXPECT_REFUSED(pset_elem_ptr_label(2), 205, Pfn_set_elem_ptr_label); /* only after the pointer */
    pdel_elem();
    CHECK(pointer() == 2 && label_at(1, 3, store) == 4);
    pset_elem_ptr(3);
    EXPECT_NO_ERROR(pdel_elem_range(0, 0)); /* deletes nothing: the pointer stays (ISO 9592) */
    CHECK(pointer() == 3);
    pdel_elem_range(4, 2);
    CHECK(pointer() == 1 && label_at(1, 2, store) == -1);
    pset_edit_mode(PEDIT_REPLACE);
    plabel(10);
    CHECK(label_at(1, 1, store) == 10 && pointer() == 1);
    pset_edit_mode(PEDIT_INSERT);
    EXPECT_ERROR(pset_edit_mode((Pedit_mode)5), PE_ENUM_TYPE_INVAL, Pfn_set_edit_mode);
    pclose_struct();
}

static void labels_between(Pstore store) {
    labels(2, 1, 6);
    popen_struct(2);
    pset_elem_ptr(0);
    pdel_elems_labels(2, 5);
    CHECK(pointer() == 2 && label_at(2, 3, store) == 5);
    EXPECT_REFUSED(pdel_elems_labels(5, 9), 206, Pfn_del_elems_labels);
    pclose_struct();
    EXPECT_REFUSED(pset_elem_ptr(1), 5, Pfn_set_elem_ptr);
    EXPECT_REFUSED(pdel_elem_range(1, 2), 5, Pfn_del_elem_range);
    EXPECT_REFUSED(pcopy_all_elems_struct(2), 5, Pfn_copy_all_elems_struct);
    EXPECT_REFUSED(pclose_struct(), 5, Pfn_close_struct);
    popen_struct(3);
    EXPECT_REFUSED(popen_struct(4), 6, Pfn_open_struct);
    pclose_struct();
}

/* The cases the ISO semantics audit found. */
static void missing_structures(Pstore store) {
    EXPECT_NO_ERROR(pempty_struct(40)); /* creates it, empty */
    CHECK(status_of(40) == PSTRUCT_STATUS_EMPTY);
    popen_struct(1);
    pset_elem_ptr(1);
    EXPECT_NO_ERROR(pcopy_all_elems_struct(77)); /* nothing to copy, no error 201 */
    CHECK(pointer() == 1);
    EXPECT_NO_ERROR(pcopy_all_elems_struct(2));
    CHECK(pointer() == 5 && label_at(1, 2, store) == 1);
    pclose_struct();
    EXPECT_NO_ERROR(pdel_struct_net(77, PFLAG_DEL));
    EXPECT_NO_ERROR(pdel_struct_net(77, PFLAG_KEEP));
    CHECK(status_of(77) == PSTRUCT_STATUS_NON_EXIST);
    EXPECT_NO_ERROR(pchange_struct_id(78, 79)); /* the result is created empty */
    CHECK(status_of(78) == PSTRUCT_STATUS_NON_EXIST && status_of(79) == PSTRUCT_STATUS_EMPTY);
    EXPECT_NO_ERROR(pchange_struct_id_refs(80, 80)); /* the same missing id: created */
    CHECK(status_of(80) == PSTRUCT_STATUS_EMPTY);
    EXPECT_NO_ERROR(pchange_struct_refs(81, 82)); /* nothing references 81: 82 not created */
    CHECK(status_of(82) == PSTRUCT_STATUS_NON_EXIST);
    EXPECT_REFUSED(pdel_struct_net(1, (Pref_flag)9), PE_ENUM_TYPE_INVAL, Pfn_del_struct_net);
}

static void networks(void) {
    Pint err = -1;
    popen_struct(50);
    pexec_struct(51);
    pclose_struct();
    CHECK(status_of(51) == PSTRUCT_STATUS_EMPTY); /* EXECUTE STRUCTURE creates it */
    popen_struct(51);
    EXPECT_REFUSED(pexec_struct(50), -201, Pfn_exec_struct); /* a cycle */
    pclose_struct();
    pchange_struct_id_refs(51, 52);
    CHECK(status_of(51) == PSTRUCT_STATUS_NON_EXIST && status_of(52) == PSTRUCT_STATUS_EMPTY);
    pdel_struct_net(50, PFLAG_DEL);
    CHECK(status_of(50) == PSTRUCT_STATUS_NON_EXIST && status_of(52) == PSTRUCT_STATUS_NON_EXIST);
    pdel_all_structs();
    {
        Pint total = -1;
        pinq_struct_ids(0, 0, &err, NULL, &total);
        CHECK(err == 0 && total == 0);
    }
}

int main(int argc, char** argv) {
    char file[512];
    Pint err = -1;
    Pstore store = NULL;
    snprintf(file, sizeof file, "%s/structures_errors.txt", argc > 1 ? argv[1] : ".");
    open_with_handler(file);
    pcreate_store(&err, &store);
    CHECK(err == 0 && store != NULL);
    pointer_moves(store);
    labels_between(store);
    missing_structures(store);
    networks();
    CHECK(file_has_line(file,
                        "ERROR 205 in SET ELEMENT POINTER AT LABEL (function 100): Ignoring function, the "
                        "label does not exist in the open structure between the element pointer and the end "
                        "of the structure"));
    CHECK(file_has_line(file,
                        "ERROR -201 in EXECUTE STRUCTURE (function 92): Ignoring function, executing this "
                        "structure would make the structure network cyclic"));
    pdel_store(store);
    pclose_phigs();
    return finish("test_structures");
}
