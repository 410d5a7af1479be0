/* A downstream C program: a structure built through phigs.h and inquired. Prints
 * "consumer_c: ok" on success. */
#include <phigs.h>
#include <stdio.h>

int main(void) {
    Ppoint3 points[2] = {{0, 0, 0}, {1, 1, 0}};
    Ppoint_list3 line = {2, points};
    Pint err = 0;
    Pstruct_status status;
    Pelem_type type;
    size_t size;
    popen_phigs(NULL, PDEF_MEM_SIZE);
    popen_struct(7);
    pset_line_colr_ind(2);
    ppolyline3(&line);
    pclose_struct();
    pinq_struct_status(7, &err, &status);
    pinq_elem_type_size(7, 2, &err, &type, &size);
    pclose_phigs();
    if (err != 0 || status != PSTRUCT_STATUS_NOT_EMPTY || type != PELEM_POLYLINE3) {
        printf("consumer_c: FAILED (error %d)\n", (int)err);
        return 1;
    }
    printf("consumer_c: ok\n");
    return 0;
}
