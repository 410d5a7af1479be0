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
    pclose_ar_file(1);
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
