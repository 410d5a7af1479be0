/* Archives: archive and retrieve with each conflict resolution, a structure the archive lacks
 * (retrieved empty with warning 408), delete from the archive (407 for missing ones), the
 * archive inquiries. argv[1]: a directory for the archive and the error file. */
#include "check.h"

static Pint count_of(Pint id) {
    Pint err = -1, n = 0;
    Pelem_type type;
    size_t size;
    for (;;) {
        pinq_elem_type_size(id, n + 1, &err, &type, &size);
        if (err != 0) return err == 201 ? -1 : n;
        ++n;
    }
}

static void build(Pint id, Pint labels) {
    popen_struct(id);
    pempty_struct(id);
    for (Pint l = 0; l < labels; ++l) plabel(l);
    pclose_struct();
}

/* Networks: 10 executes 11, 11 executes 12; archive, retrieve and delete them as networks. */
static void networks(Pstore store) {
    Pint err = -1, total = -1, buffer[8], ten[1] = {10}, eleven[1] = {11};
    Pint_list ids = {0, buffer}, list_ten = {1, ten}, list_eleven = {1, eleven};
    Pelem_ref_list_list* paths = NULL;
    popen_struct(10);
    pexec_struct(11);
    pclose_struct();
    popen_struct(11);
    plabel(1);
    pexec_struct(12);
    pclose_struct();
    EXPECT_NO_ERROR(par_struct_nets(1, &list_ten));
    pret_struct_ids(1, 8, 0, &ids, &total);
    CHECK(total == 3 && buffer[0] == 10 && buffer[2] == 12);
    EXPECT_NO_ERROR(pret_paths_ances(1, 12, PORDER_TOP_FIRST, 0, store, &paths));
    CHECK(paths != NULL && paths->num_elem_ref_lists == 1 && paths->elem_ref_lists[0].num_elem_refs == 3);
    if (paths && paths->num_elem_ref_lists == 1)
        CHECK(paths->elem_ref_lists[0].elem_refs[1].struct_id == 11 &&
              paths->elem_ref_lists[0].elem_refs[1].elem_pos == 2);
    EXPECT_NO_ERROR(pret_paths_descs(1, 10, PORDER_BOTTOM_FIRST, 1, store, &paths));
    CHECK(paths->num_elem_ref_lists == 1 && paths->elem_ref_lists[0].elem_refs[0].struct_id == 12);
    EXPECT_ERROR(pret_paths_descs(1, 10, PORDER_TOP_FIRST, -1, store, &paths), 207, Pfn_ret_paths_descs);
    pempty_struct(13);
    par_structs(1, &(Pint_list){1, (Pint[]){13}});
    EXPECT_NO_ERROR(pret_paths_ances(1, 13, PORDER_TOP_FIRST, 0, store, &paths)); /* isolated: none */
    CHECK(paths->num_elem_ref_lists == 0);
    EXPECT_NO_ERROR(pret_paths_descs(1, 13, PORDER_TOP_FIRST, 0, store, &paths));
    CHECK(paths->num_elem_ref_lists == 0);
    pdel_structs_ar(1, &(Pint_list){1, (Pint[]){13}});
    pdel_struct(13);
    pinq_conf_structs_net(1, 10, PNET_CSS, 8, 0, &err, &ids, &total);
    CHECK(err == 0 && total == 3);
    pinq_conf_structs_net(1, 11, PNET_AR, 1, 1, &err, &ids, &total);
    CHECK(err == 0 && total == 2 && ids.num_ints == 1 && buffer[0] == 12);
    pinq_conf_structs_net(1, 11, (Pstruct_net_source)7, 1, 0, &err, &ids, &total);
    CHECK(err == PE_ENUM_TYPE_INVAL);
    pdel_all_structs();
    pset_conf_res(PRES_UPDATE, PRES_ABANDON);
    EXPECT_NO_ERROR(pret_struct_nets(1, &list_eleven));
    CHECK(count_of(11) == 2 && count_of(12) == 0 && count_of(10) == -1);
    pdel_all_structs();
    EXPECT_NO_ERROR(pret_all_structs(1));
    CHECK(count_of(10) == 1 && count_of(11) == 2);
    EXPECT_NO_ERROR(pdel_all_structs_ar(1));
    pret_struct_ids(1, 8, 0, &ids, &total);
    CHECK(total == 0);
    EXPECT_NO_ERROR(par_all_structs(1));
    pret_struct_ids(1, 8, 0, &ids, &total);
    CHECK(total == 3);
    EXPECT_NO_ERROR(pdel_all_structs_ar(1));
    pdel_all_structs();
}

/* The archive checksum (REFERENCE.md): FNV-1a of the text before the END line. */
static unsigned long long checksum(const char* text) {
    unsigned long long h = 1469598103934665603ULL;
    for (; *text; ++text) h = (h ^ (unsigned char)*text) * 1099511628211ULL;
    return h;
}

/* The store keeps doubles, so an archive written elsewhere may hold a real no Pfloat holds
 * (1e300): it is retrieved as it is, and INQUIRE ELEMENT CONTENT answers error 908 (arithmetic)
 * instead of an infinity; a real within a Pfloat's range still answers. */
static void beyond_pfloat(const char* dir, Pstore store) {
    const char* body =
        "PHIGS-ARCHIVE 3\nSTRUCTURE 31 2\nSET_MARKER_SIZE_SCALE_FACTOR 1e300\n"
        "SET_MARKER_SIZE_SCALE_FACTOR 3e38\n";
    char path[512];
    snprintf(path, sizeof path, "%s/beyond_pfloat.phar", dir);
    FILE* f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f) return;
    fprintf(f, "%sEND 1 %016llx\n", body, checksum(body));
    fclose(f);
    Pint err = -1;
    Pelem_data* data = NULL;
    EXPECT_NO_ERROR(popen_ar_file(5, path));
    EXPECT_NO_ERROR(pret_all_structs(5));
    pinq_elem_content(31, 1, store, &err, &data);
    CHECK(err == 908);
    pinq_elem_content(31, 2, store, &err, &data);
    CHECK(err == 0 && data != NULL && data->float_data == 3e38f);
    pclose_ar_file(5);
    pdel_struct(31);
    remove(path);
}

int main(int argc, char** argv) {
    char file[512], archive[512];
    Pint err = -1, total = -1, buffer[8], one[1] = {1}, two[1] = {2}, missing[2] = {1, 9};
    Pint_list ids = {0, buffer}, list_one = {1, one}, list_two = {1, two}, list_missing = {2, missing};
    Pstore store = NULL;
    Par_file_list* files = NULL;
    Par_st st = PAR_ST_OP;
    Pconf_res archival = PRES_MAINTAIN, retrieval = PRES_MAINTAIN;
    const char* dir = argc > 1 ? argv[1] : ".";
    snprintf(file, sizeof file, "%s/archive_errors.txt", dir);
    snprintf(archive, sizeof archive, "%s/c_binding.phar", dir);
    remove(archive);
    open_with_handler(file);
    pcreate_store(&err, &store);

    EXPECT_ERROR(par_structs(1, &list_one), 7, Pfn_ar_structs);
    /* a file that cannot be created is error 400 alone, and no archive is open */
    EXPECT_ERROR(popen_ar_file(1, "/nonexistent-directory/x.phar"), 400, Pfn_open_ar_file);
    EXPECT_ERROR(popen_ar_file(1, ""), 400, Pfn_open_ar_file);
    pinq_ar_st(&st);
    CHECK(st == PAR_ST_CL);
    popen_ar_file(1, archive);
    pinq_ar_st(&st);
    CHECK(st == PAR_ST_OP);
    EXPECT_ERROR(popen_ar_file(1, archive), 402, Pfn_open_ar_file);
    EXPECT_ERROR(par_structs(2, &list_one), 404, Pfn_ar_structs);
    EXPECT_ERROR(par_structs(1, NULL), -204, Pfn_ar_structs);
    build(1, 3);
    EXPECT_NO_ERROR(par_structs(1, &list_one));
    pret_struct_ids(1, 8, 0, &ids, &total);
    CHECK(total == 1 && ids.num_ints == 1 && buffer[0] == 1);
    pinq_ar_files(store, &err, &files);
    CHECK(err == 0 && files->num_ar_files == 1 && files->ar_files[0].ar_id == 1);
    CHECK(strcmp(files->ar_files[0].name, archive) == 0);
    pinq_conf_res(&err, &archival, &retrieval);
    CHECK(err == 0 && archival == PRES_UPDATE && retrieval == PRES_ABANDON);
    pinq_all_conf_structs(1, 8, 0, &err, &ids, &total);
    CHECK(err == 0 && total == 1 && buffer[0] == 1);

    build(2, 2);                                                      /* only in the CSS */
    EXPECT_REFUSED(pret_structs(1, &list_two), 405, Pfn_ret_structs); /* ABANDON: empty meets 2 */
    CHECK(count_of(2) == 2);
    EXPECT_ERROR(pret_structs(1, &list_missing), 405, Pfn_ret_structs); /* 1 conflicts */
    pset_conf_res(PRES_UPDATE, PRES_MAINTAIN);
    EXPECT_ERROR(pret_structs(1, &list_two), 408, Pfn_ret_structs);
    CHECK(count_of(2) == 2);
    pset_conf_res(PRES_UPDATE, PRES_UPDATE);
    EXPECT_ERROR(pret_structs(1, &list_two), 408, Pfn_ret_structs); /* UPDATE empties it */
    CHECK(count_of(2) == 0);
    pdel_all_structs();
    EXPECT_ERROR(pret_structs(1, &list_missing), 408, Pfn_ret_structs); /* 9: created empty */
    CHECK(count_of(1) == 3 && count_of(9) == 0);
    EXPECT_ERROR(pset_conf_res((Pconf_res)5, PRES_UPDATE), PE_ENUM_TYPE_INVAL, Pfn_set_conf_res);

    EXPECT_ERROR(pdel_struct_nets_ar(1, &list_missing), 407, Pfn_del_struct_nets_ar);
    pret_struct_ids(1, 8, 0, &ids, &total);
    CHECK(total == 0);
    EXPECT_ERROR(pdel_structs_ar(1, &list_one), 407, Pfn_del_structs_ar);
    pdel_all_structs();
    networks(store);
    beyond_pfloat(dir, store);
    pclose_ar_file(1);
    EXPECT_ERROR(pret_all_structs(1), 7, Pfn_ret_all_structs);
    pinq_ar_st(&st);
    CHECK(st == PAR_ST_CL);
    CHECK(file_has_line(file,
                        "WARNING 408 in RETRIEVE STRUCTURES (function 121): Warning, some of the specified "
                        "structures do not exist on the archive file. PHIGS will create empty structures in "
                        "their places"));
    CHECK(file_has_line(file,
                        "ERROR 405 in RETRIEVE STRUCTURES (function 121): Ignoring function, name conflict "
                        "occurred while conflict resolution flag has value ABANDON"));
    pdel_store(store);
    pclose_phigs();
    remove(archive);
    return finish("test_archive");
}
