/* Structure and CSS inquiries: the simple list rules (start index, application list length),
 * Pstore answers for paths and contents, ELEMENT SEARCH and INQUIRE ELEMENT TYPE AND SIZE at
 * position 0 (NIL), isolated structures (no paths), and no handler call from any of them. */
#include "check.h"

static void network(void) {
    /* 101 -> 102 (1), 103 (2); 102 -> 104 (1); 103 -> 104 (1), 104 (2); 105 alone */
    popen_struct(101);
    pexec_struct(102);
    pexec_struct(103);
    pclose_struct();
    popen_struct(102);
    pexec_struct(104);
    pclose_struct();
    popen_struct(103);
    pexec_struct(104);
    plabel(7);
    pexec_struct(104);
    pclose_struct();
    pempty_struct(105);
}

static void lists(void) {
    Pint err = -1, total = -1, buffer[3] = {0, 0, 0};
    Pint_list ids = {0, buffer};
    pinq_struct_ids(3, 0, &err, &ids, &total);
    CHECK(err == 0 && total == 5 && ids.num_ints == 3 && buffer[0] == 101 && buffer[2] == 103);
    pinq_struct_ids(3, 3, &err, &ids, &total);
    CHECK(err == 0 && ids.num_ints == 2 && buffer[0] == 104 && buffer[1] == 105);
    pinq_struct_ids(0, 4, &err, &ids, &total);
    CHECK(err == 0 && ids.num_ints == 0 && total == 5);
    pinq_struct_ids(3, 5, &err, &ids, &total);
    CHECK(err == PE_START_IND_INVAL);
    pinq_struct_ids(3, -1, &err, &ids, &total);
    CHECK(err == PE_START_IND_INVAL);
    pinq_struct_ids(-1, 0, &err, &ids, &total);
    CHECK(err == PE_LIST_LENGTH_LT_ZERO);
}

static void paths(Pstore store) {
    Pint err = -1;
    Pelem_ref_list_list* p = NULL;
    pinq_paths_ances(104, PORDER_TOP_FIRST, 0, store, &err, &p);
    CHECK(err == 0 && p != NULL && p->num_elem_ref_lists == 3);
    if (err == 0 && p->num_elem_ref_lists == 3) {
        const Pelem_ref_list* first = &p->elem_ref_lists[0];
        const Pelem_ref_list* last = &p->elem_ref_lists[2];
        CHECK(first->num_elem_refs == 3 && first->elem_refs[0].struct_id == 101 &&
              first->elem_refs[0].elem_pos == 1);
        CHECK(first->elem_refs[2].struct_id == 104 && first->elem_refs[2].elem_pos == 0);
        CHECK(last->elem_refs[1].struct_id == 103 && last->elem_refs[1].elem_pos == 3);
    }
    pinq_paths_descs(101, PORDER_TOP_FIRST, 1, store, &err, &p);
    CHECK(err == 0 && p->num_elem_ref_lists == 2 && p->elem_ref_lists[0].num_elem_refs == 1);
    pinq_paths_ances(105, PORDER_TOP_FIRST, 0, store, &err, &p); /* isolated: no path */
    CHECK(err == 0 && p->num_elem_ref_lists == 0);
    pinq_paths_descs(105, PORDER_TOP_FIRST, 0, store, &err, &p);
    CHECK(err == 0 && p->num_elem_ref_lists == 0);
    pinq_paths_ances(106, PORDER_TOP_FIRST, 0, store, &err, &p);
    CHECK(err == 201);
    pinq_paths_ances(104, PORDER_TOP_FIRST, -1, store, &err, &p);
    CHECK(err == 207);
    pinq_paths_ances(104, (Ppath_order)4, 0, store, &err, &p);
    CHECK(err == PE_ENUM_TYPE_INVAL);
    pinq_paths_ances(104, PORDER_TOP_FIRST, 0, NULL, &err, &p);
    CHECK(err == PE_ALLOC_STORE);
}

static void search_and_sizes(Pstore store) {
    Pint err = -1, found = -1;
    Psearch_status status = PSEARCH_STATUS_FAILURE;
    Pelem_type all[1] = {PELEM_ALL}, nil[1] = {PELEM_NIL}, labels[1] = {PELEM_LABEL},
               bad[1] = {(Pelem_type)999};
    Pelem_type_list incl_all = {1, all}, incl_nil = {1, nil}, incl_label = {1, labels}, none = {0, NULL};
    Pelem_type_list incl_bad = {1, bad};
    Pelem_type type = PELEM_ALL;
    size_t size = 99;
    Pelem_data* data = NULL;

    pelem_search(103, 0, PDIR_FORWARD, &incl_all, &none, &err, &status, &found);
    CHECK(err == 0 && status == PSEARCH_STATUS_SUCCESS && found == 0); /* NIL at 0 */
    pelem_search(103, 3, PDIR_BACKWARD, &incl_nil, &none, &err, &status, &found);
    CHECK(err == 0 && status == PSEARCH_STATUS_SUCCESS && found == 0);
    pelem_search(103, 0, PDIR_FORWARD, &incl_label, &none, &err, &status, &found);
    CHECK(err == 0 && status == PSEARCH_STATUS_SUCCESS && found == 2);
    pelem_search(103, 0, PDIR_FORWARD, &incl_all, &incl_nil, &err, &status, &found);
    CHECK(err == 0 && found == 1);
    pelem_search(103, 3, PDIR_FORWARD, &incl_label, &none, &err, &status, &found);
    CHECK(err == 0 && status == PSEARCH_STATUS_FAILURE);
    pelem_search(106, 0, PDIR_FORWARD, &incl_all, &none, &err, &status, &found);
    CHECK(err == 201);
    pelem_search(103, 0, PDIR_FORWARD, &incl_bad, &none, &err, &status, &found);
    CHECK(err == PE_ENUM_TYPE_INVAL);
    pelem_search(103, 0, (Psearch_dir)3, &incl_all, &none, &err, &status, &found);
    CHECK(err == PE_ENUM_TYPE_INVAL);

    pinq_elem_type_size(103, 0, &err, &type, &size);
    CHECK(err == 0 && type == PELEM_NIL && size == 0);
    pinq_elem_type_size(103, 4, &err, &type, &size);
    CHECK(err == 202);
    pinq_elem_type_size(103, 2, &err, &type, &size);
    CHECK(err == 0 && type == PELEM_LABEL && size > 0);
    pinq_elem_content(103, 9, store, &err, &data);
    CHECK(err == 202);
    pinq_elem_content(103, 1, NULL, &err, &data);
    CHECK(err == PE_ALLOC_STORE);

    popen_struct(103);
    pset_elem_ptr(0);
    pinq_cur_elem_type_size(&err, &type, &size);
    CHECK(err == 0 && type == PELEM_NIL && size == 0);
    pset_elem_ptr(2);
    pinq_cur_elem_content(store, &err, &data);
    CHECK(err == 0 && data->int_data == 7);
    pclose_struct();
    pinq_cur_elem_type_size(&err, &type, &size);
    CHECK(err == 5);
}

/* NULL where an answer should go: the binding's -204, or nothing at all without err_ind. */
static void null_arguments(Pstore store) {
    Pint err = -1, total = -1;
    size_t size = 0;
    Pelem_data* data = NULL;
    Pint_list ids = {0, NULL};
    pinq_elem_type_size(103, 1, &err, NULL, &size);
    CHECK(err == -204);
    pinq_struct_ids(3, 0, &err, &ids, &total); /* room for 3 but no array */
    CHECK(err == -204);
    pinq_struct_ids(3, 0, &err, NULL, NULL);
    CHECK(err == -204);
    pinq_elem_content(103, 1, store, &err, NULL);
    CHECK(err == -204);
    pelem_search(103, 0, PDIR_FORWARD, NULL, NULL, &err, NULL, NULL);
    CHECK(err == -204);
    pinq_elem_ptr(NULL, NULL);
    pinq_elem_content(103, 1, store, NULL, &data);
    pinq_sys_st(NULL);
    pinq_struct_st(NULL);
}

static void states(void) {
    Pint err = -1, id = -1;
    Pstruct_st st = PSTRUCT_ST_STOP;
    Popen_struct_status open = PSTRUCT_OPEN;
    Pstruct_status status = PSTRUCT_STATUS_EMPTY;
    Pedit_mode mode = PEDIT_REPLACE;
    pinq_struct_st(&st);
    CHECK(st == PSTRUCT_ST_STCL);
    pinq_open_struct(&err, &open, &id);
    CHECK(err == 0 && open == PSTRUCT_NONE);
    popen_struct(105);
    pinq_struct_st(&st);
    pinq_open_struct(&err, &open, &id);
    CHECK(st == PSTRUCT_ST_STOP && open == PSTRUCT_OPEN && id == 105);
    pclose_struct();
    pinq_struct_status(105, &err, &status);
    CHECK(err == 0 && status == PSTRUCT_STATUS_EMPTY);
    pinq_struct_status(101, &err, &status);
    CHECK(err == 0 && status == PSTRUCT_STATUS_NOT_EMPTY);
    pinq_struct_status(999, &err, &status);
    CHECK(err == 0 && status == PSTRUCT_STATUS_NON_EXIST);
    pinq_edit_mode(&err, &mode);
    CHECK(err == 0 && mode == PEDIT_INSERT);
}

int main(int argc, char** argv) {
    char file[512];
    Pint err = -1;
    Pstore store = NULL;
    snprintf(file, sizeof file, "%s/inquiries_errors.txt", argc > 1 ? argv[1] : ".");
    open_with_handler(file);
    pcreate_store(&err, &store);
    network();
    error_count = 0;
    lists();
    paths(store);
    search_and_sizes(store);
    null_arguments(store);
    states();
    CHECK(error_count == 0); /* no inquiry called the handler */
    CHECK(file_line_count(file) == 0);
    pdel_store(store);
    pclose_phigs();
    return finish("test_inquiries");
}
