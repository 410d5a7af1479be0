/* phigs.h: the ISO C binding of PHIGS (ISO/IEC 9593-4) over this toolkit, part 1: control,
 * error handling, structures and their elements, archives, the transformation utilities and
 * the structure, CSS and archive inquiries. Written for this project from the standard's
 * published interface (names, types and constants); phigs/c/README.md lists what is done.
 * C11 and C++ clean; nothing of the toolkit's C++ is visible here. */
#ifndef PHIGS_C_BINDING_H
#define PHIGS_C_BINDING_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- basic types */
typedef int Pint;
typedef float Pfloat;
typedef long Plong;

/* OPEN PHIGS defaults: no error file (errors go to stderr), the memory the system has. */
#define PDEF_MEM_SIZE ((size_t)(-1))
#define PDEF_ERR_FILE ((char*)0)

/* ---- error numbers (ISO 9592 and PHIGS PLUS, by the binding's names) */
#define PE_NO_ERROR 0
#define PE_NOT_PHCL 1
#define PE_NOT_PHOP 2
#define PE_NOT_WSOP 3
#define PE_NOT_CL 4
#define PE_NOT_STOP 5
#define PE_NOT_STCL 6
#define PE_NOT_AROP 7
#define PE_BAD_CONN_ID 50
#define PE_WS_TYPE 51
#define PE_BAD_WS_TYPE 52
#define PE_DUP_WS_ID 53
#define PE_WS_NOT_OPEN 54
#define PE_NO_OPEN_WS 55
#define PE_WS_NOT_MO 56
#define PE_WS_MI 57
#define PE_WS_NOT_MI 58
#define PE_WS_NO_OUTPUT 59
#define PE_WS_NOT_OUTIN 60
#define PE_WS_NO_INPUT 61
#define PE_WS_NOT_OUT 62
#define PE_MAX_WS 63
#define PE_NO_GDP 64
#define PE_BUN_IND_LT_1 100
#define PE_REP_UNDEF 101
#define PE_REP_NOT_PREDEF 102
#define PE_MAX_BUN 103
#define PE_BAD_LINETYPE 104
#define PE_BAD_MARKER_TYPE 105
#define PE_BAD_FONT 106
#define PE_BAD_EDGETYPE 107
#define PE_BAD_INT_STYLE 108
#define PE_NO_PAT 109
#define PE_BAD_COLR_MODEL 110
#define PE_BAD_HLHSR_MODE 111
#define PE_PAT_IND_LT_1 112
#define PE_COLR_IND_LT_0 113
#define PE_VIEW_IND_LT_0 114
#define PE_VIEW_IND_LT_1 115
#define PE_BAD_PAT_DIM 116
#define PE_BAD_COLR_DIM 117
#define PE_BAD_COLR 118
#define PE_DCUE_INDX_LT_0 119
#define PE_DCUE_INDX_LT_1 120
#define PE_COLRMAP_INDX_LT_0 121
#define PE_BAD_LINE_SHADE 122
#define PE_BAD_INT_SHADE 123
#define PE_BAD_REF_EQN 124
#define PE_BAD_COLRMAP_RANGE 125
#define PE_BAD_COLRMAP_METHOD 126
#define PE_LTSRC_INDX_LT_1 129
#define PE_BAD_REF_PLANES 130
#define PE_BAD_LTSRCTYPE 131
#define PE_BAD_LTANGLE 132
#define PE_ENTRY_LT_1 133
#define PE_NOT_INDIRECT 134
#define PE_DUP_ENTRY 135
#define PE_BAD_COLR_RANGE 136
#define PE_BAD_DATA 138
#define PE_MAX_VIEW 150
#define PE_INVALID_WINDOW 151
#define PE_INVALID_VIEWPORT 152
#define PE_INVALID_CLIP 153
#define PE_BAD_CLIP 154
#define PE_BAD_PROJ_VIEWPORT 155
#define PE_BAD_WS_WINDOW 156
#define PE_BAD_WS_VIEWPORT 157
#define PE_BAD_PLANES 158
#define PE_BAD_VPN 159
#define PE_BAD_VUP 160
#define PE_BAD_VUP_VPN 161
#define PE_BAD_PRP 162
#define PE_PRP_VIEW_PLANE 163
#define PE_FRONT_BACK 164
#define PE_IGNORE_STRUCTS 200
#define PE_BAD_STRUCT 201
#define PE_BAD_ELEMENT 202
#define PE_BAD_PATH 203
#define PE_BAD_CEILING_IND 204
#define PE_NO_LABEL 205
#define PE_NO_LABELS 206
#define PE_BAD_PATH_DEPTH 207
#define PE_BAD_DISP_PRI 208
#define PE_NO_DEVICE 250
#define PE_NOT_REQUEST 251
#define PE_NOT_SAMPLE 252
#define PE_BAD_PET 253
#define PE_INVALID_ECHO 254
#define PE_BAD_ECHO 255
#define PE_QUEUE_OFLOW 256
#define PE_NO_QUEUE_OFLOW 257
#define PE_OFLOW_NO_GO 258
#define PE_BAD_CLASS 259
#define PE_BAD_DATA_REC 260
#define PE_INVALID_VALUE 261
#define PE_STROKE_BUF_SIZE 262
#define PE_STRING_BUF_SIZE 263
#define PE_ILLEGAL_ITEM_TYPE 300
#define PE_INVALID_ITEM_LENGTH 301
#define PE_METAFILE_EMPTY 302
#define PE_INVALID_ITEM 303
#define PE_BAD_ITEM_TYPE 304
#define PE_BAD_ITEM_REC 305
#define PE_MAX_ITEM_LENGTH 306
#define PE_USER_ITEM 307
#define PE_ESCAPE_NOT_AVAIL 350
#define PE_BAD_ESCAPE_DATA 351
#define PE_AR_CANT_OPEN 400
#define PE_MAX_AR 401
#define PE_DUP_AR_ID 402
#define PE_BAD_AR 403
#define PE_AR_NOT_OPEN 404
#define PE_NAME_CONFLICT 405
#define PE_AR_FULL 406
#define PE_AR_NO_STRUCT 407
#define PE_AR_NO_STRUCT_EMPTY 408
#define PE_BAD_ERROR_FILE 450
#define PE_ORDER_LT_1 500
#define PE_CTL_POINTS 501
#define PE_BAD_ORDER 502
#define PE_BAD_KNOTS 503
#define PE_BAD_VERT_INDX 504
#define PE_DEGEN_FAS 505
#define PE_BAD_PARAM_RANGE 506
#define PE_BAD_EDGE_FLAG 513
#define PE_OFLOW_PHIGS 900
#define PE_OFLOW_CSS 901
#define PE_IO_ERROR_READ 902
#define PE_IO_ERROR_WRITE 903
#define PE_IO_ERROR_TO_WS 904
#define PE_IO_ERROR_FROM_WS 905
#define PE_IO_ERROR_LIB 906
#define PE_IO_ERROR_WDT 907
#define PE_ARITHMETIC_ERROR 908
/* ---- C binding error numbers (ISO 9593-4) */
#define PE_START_IND_INVAL 2200     /* start index out of range */
#define PE_LIST_LENGTH_LT_ZERO 2201 /* the length of the application's list is negative */
#define PE_ENUM_TYPE_INVAL 2202     /* enumeration type out of range */
#define PE_ALLOC_STORE 2203         /* error while allocating a Store */
#define PE_ALLOC_STORE_MEM 2204     /* error while allocating memory for a Store */

/* ---- geometry */
typedef struct {
    Pfloat x, y;
} Ppoint;
typedef struct {
    Pfloat x, y, z;
} Ppoint3;
typedef struct {
    Pfloat delta_x, delta_y;
} Pvec;
typedef struct {
    Pfloat delta_x, delta_y, delta_z;
} Pvec3;
typedef Pfloat Pmatrix[3][3];  /* [row][column], x' = M x: translation in the last column */
typedef Pfloat Pmatrix3[4][4]; /* likewise */
typedef struct {
    Pint num_points;
    Ppoint* points;
} Ppoint_list;
typedef struct {
    Pint num_points;
    Ppoint3* points;
} Ppoint_list3;
typedef struct {
    Pint num_point_lists;
    Ppoint_list* point_lists;
} Ppoint_list_list;
typedef struct {
    Pint num_point_lists;
    Ppoint_list3* point_lists;
} Ppoint_list_list3;
typedef struct {
    Pint num_ints;
    Pint* ints;
} Pint_list;
typedef struct {
    Pfloat x_min, x_max, y_min, y_max;
} Plimit;
typedef struct {
    Pfloat x_min, x_max, y_min, y_max, z_min, z_max;
} Plimit3;
typedef struct {
    Ppoint p, q;
} Prect;
typedef struct {
    Ppoint3 p, q, r;
} Pparal;
typedef struct {
    Pint size_x, size_y;
} Pint_size;
typedef struct {
    Pfloat size_x, size_y;
} Pfloat_size;
typedef struct {
    Pint_size dims;
    Pint* colr_array; /* dims.size_x * dims.size_y colour indices, row by row */
} Ppat_rep;
typedef struct {
    Ppoint point;
    Pvec norm;
} Phalf_space;
typedef struct {
    Ppoint3 point;
    Pvec3 norm;
} Phalf_space3;
typedef struct {
    Pint num_half_spaces;
    Phalf_space* half_spaces;
} Phalf_space_list;
typedef struct {
    Pint num_half_spaces;
    Phalf_space3* half_spaces;
} Phalf_space_list3;
typedef struct {
    Pint size;
    void* data;
} Pdata;
/* ESCAPE data records. This implementation registers one escape, PUESC_INPUT_SCRIPT (-11, its
 * record escape_in_u11; see the input section below); any other identifier is answered with
 * warning 350. The output record is always NULL. */
typedef union {
    struct {
        Pint unused;
    } escape_in_u1;
    struct {
        Pint ws_id;
        const char* script; /* the script's text, or NULL to read it from `file` */
        const char* file;
    } escape_in_u11;
    Pdata unsupp;
} Pescape_in_data;
typedef union {
    struct {
        Pint unused;
    } escape_out_u1;
    Pdata unsupp;
} Pescape_out_data;
/* GDP and GSE data records. This implementation's GDPs (GDP_CIRCLE, GDP_ARC) need none; the
 * record of any other identifier is kept as the bytes `unsupp` gives. */
typedef union {
    struct {
        Pint unused;
    } gdp3_r1;
    Pdata unsupp;
} Pgdp_data3;
typedef union {
    struct {
        Pint unused;
    } gdp_r1;
    Pdata unsupp;
} Pgdp_data;
typedef union {
    struct {
        Pint unused;
    } gse_r1;
    Pdata unsupp;
} Pgse_data;
/* The GDP identifiers this implementation draws (implementation-defined, hence negative):
 * GDP_CIRCLE: centre, a point on the circle and, for pgdp3, a third point fixing its plane;
 * GDP_ARC: three points on a circular arc, start, any point between, end. Any other
 * identifier is stored and not drawn. */
#define PGDP_CIRCLE (-1)
#define PGDP_ARC (-2)

/* ---- enumerations */
typedef enum { PSYS_ST_PHCL, PSYS_ST_PHOP } Psys_st;
typedef enum { PSTRUCT_ST_STCL, PSTRUCT_ST_STOP } Pstruct_st;
typedef enum { PAR_ST_CL, PAR_ST_OP } Par_st;
typedef enum { PSTRUCT_NONE, PSTRUCT_OPEN } Popen_struct_status;
typedef enum { PEDIT_INSERT, PEDIT_REPLACE } Pedit_mode;
typedef enum { PSTRUCT_STATUS_NON_EXIST, PSTRUCT_STATUS_EMPTY, PSTRUCT_STATUS_NOT_EMPTY } Pstruct_status;
typedef enum { PDIR_BACKWARD, PDIR_FORWARD } Psearch_dir;
typedef enum { PSEARCH_STATUS_FAILURE, PSEARCH_STATUS_SUCCESS } Psearch_status;
typedef enum { PFLAG_DEL, PFLAG_KEEP } Pref_flag;
typedef enum { PORDER_TOP_FIRST, PORDER_BOTTOM_FIRST } Ppath_order;
typedef enum { PTYPE_PRECONCAT, PTYPE_POSTCONCAT, PTYPE_REPLACE } Pcompose_type;
typedef enum { PRES_MAINTAIN, PRES_ABANDON, PRES_UPDATE } Pconf_res;
typedef enum { PNET_CSS, PNET_AR } Pstruct_net_source;
typedef enum { PERR_OFF, PERR_ON } Perr_mode;
typedef enum { PTYPE_PARAL, PTYPE_PERSPECT } Pproj_type;
typedef enum { PPREC_STRING, PPREC_CHAR, PPREC_STROKE } Ptext_prec;
typedef enum { PPATH_RIGHT, PPATH_LEFT, PPATH_UP, PPATH_DOWN } Ptext_path;
typedef enum { PHOR_NORM, PHOR_LEFT, PHOR_CTR, PHOR_RIGHT } Phor_text_align;
typedef enum { PVERT_NORM, PVERT_TOP, PVERT_CAP, PVERT_HALF, PVERT_BASE, PVERT_BOTTOM } Pvert_text_align;
typedef struct {
    Phor_text_align hor;
    Pvert_text_align vert;
} Ptext_align;
typedef enum { PSTYLE_HOLLOW, PSTYLE_SOLID, PSTYLE_PAT, PSTYLE_HATCH, PSTYLE_EMPTY } Pint_style;
typedef enum { PEDGE_OFF, PEDGE_ON } Pedge_flag;
typedef enum { PIND_NO_CLIP, PIND_CLIP } Pclip_ind;
typedef enum { PASF_BUNDLED, PASF_INDIV } Pasf;
typedef enum {
    PASPECT_LINETYPE,
    PASPECT_LINEWIDTH,
    PASPECT_LINE_COLR_IND,
    PASPECT_MARKER_TYPE,
    PASPECT_MARKER_SIZE,
    PASPECT_MARKER_COLR_IND,
    PASPECT_TEXT_FONT,
    PASPECT_TEXT_PREC,
    PASPECT_CHAR_EXPAN,
    PASPECT_CHAR_SPACE,
    PASPECT_TEXT_COLR_IND,
    PASPECT_INT_STYLE,
    PASPECT_INT_STYLE_IND,
    PASPECT_INT_COLR_IND,
    PASPECT_EDGE_FLAG,
    PASPECT_EDGETYPE,
    PASPECT_EDGEWIDTH,
    PASPECT_EDGE_COLR_IND,
    /* PHIGS PLUS */
    PASPECT_LINE_SHAD_METH,
    PASPECT_INT_SHAD_METH,
    PASPECT_REFL_PROPS,
    PASPECT_INT_REFL_EQN,
    PASPECT_BACK_INT_STYLE,
    PASPECT_BACK_INT_STYLE_IND,
    PASPECT_BACK_INT_COLR,
    PASPECT_BACK_INT_SHAD_METH,
    PASPECT_BACK_REFL_PROPS,
    PASPECT_BACK_INT_REFL_EQN,
    PASPECT_CURVE_APPROX_CRIT,
    PASPECT_SURF_APPROX_CRIT
} Paspect;

/* Model clipping operators and the common line and marker types. */
#define PMC_REPLACE 1
#define PMC_INTERSECT 2
#define PLINE_SOLID 1
#define PLINE_DASH 2
#define PLINE_DOT 3
#define PLINE_DASH_DOT 4
#define PMARKER_DOT 1
#define PMARKER_PLUS 2
#define PMARKER_ASTERISK 3
#define PMARKER_CIRCLE 4
#define PMARKER_CROSS 5
#define PANNO_STYLE_UNCONNECTED 1
#define PANNO_STYLE_LEAD_LINE 2

/* Element types: PHIGS's in the standard's order, then the PHIGS PLUS ones this toolkit
 * stores (PELEM_*_COLR are the general-colour forms of the colour index attributes). */
typedef enum {
    PELEM_ALL,
    PELEM_NIL,
    PELEM_POLYLINE3,
    PELEM_POLYLINE,
    PELEM_POLYMARKER3,
    PELEM_POLYMARKER,
    PELEM_TEXT3,
    PELEM_TEXT,
    PELEM_ANNO_TEXT_REL3,
    PELEM_ANNO_TEXT_REL,
    PELEM_FILL_AREA3,
    PELEM_FILL_AREA,
    PELEM_FILL_AREA_SET3,
    PELEM_FILL_AREA_SET,
    PELEM_CELL_ARRAY3,
    PELEM_CELL_ARRAY,
    PELEM_GDP3,
    PELEM_GDP,
    PELEM_LINE_IND,
    PELEM_MARKER_IND,
    PELEM_TEXT_IND,
    PELEM_INT_IND,
    PELEM_EDGE_IND,
    PELEM_LINETYPE,
    PELEM_LINEWIDTH,
    PELEM_LINE_COLR_IND,
    PELEM_MARKER_TYPE,
    PELEM_MARKER_SIZE,
    PELEM_MARKER_COLR_IND,
    PELEM_TEXT_FONT,
    PELEM_TEXT_PREC,
    PELEM_CHAR_EXPAN,
    PELEM_CHAR_SPACE,
    PELEM_TEXT_COLR_IND,
    PELEM_CHAR_HT,
    PELEM_CHAR_UP_VEC,
    PELEM_TEXT_PATH,
    PELEM_TEXT_ALIGN,
    PELEM_ANNO_CHAR_HT,
    PELEM_ANNO_CHAR_UP_VEC,
    PELEM_ANNO_PATH,
    PELEM_ANNO_ALIGN,
    PELEM_ANNO_STYLE,
    PELEM_INT_STYLE,
    PELEM_INT_STYLE_IND,
    PELEM_INT_COLR_IND,
    PELEM_EDGE_FLAG,
    PELEM_EDGETYPE,
    PELEM_EDGEWIDTH,
    PELEM_EDGE_COLR_IND,
    PELEM_PAT_SIZE,
    PELEM_PAT_REF_POINT_VECS,
    PELEM_PAT_REF_POINT,
    PELEM_ADD_NAMES_SET,
    PELEM_REMOVE_NAMES_SET,
    PELEM_INDIV_ASF,
    PELEM_HLHSR_ID,
    PELEM_LOCAL_MODEL_TRAN3,
    PELEM_LOCAL_MODEL_TRAN,
    PELEM_GLOBAL_MODEL_TRAN3,
    PELEM_GLOBAL_MODEL_TRAN,
    PELEM_MODEL_CLIP_VOL3,
    PELEM_MODEL_CLIP_VOL,
    PELEM_MODEL_CLIP_IND,
    PELEM_RESTORE_MODEL_CLIP_VOL,
    PELEM_VIEW_IND,
    PELEM_EXEC_STRUCT,
    PELEM_LABEL,
    PELEM_APPL_DATA,
    PELEM_GSE,
    PELEM_PICK_ID,
    /* PHIGS PLUS */
    PELEM_LINE_COLR,
    PELEM_MARKER_COLR,
    PELEM_TEXT_COLR,
    PELEM_INT_COLR,
    PELEM_BACK_INT_COLR,
    PELEM_EDGE_COLR,
    PELEM_BACK_INT_COLR_IND,
    PELEM_LINE_SHAD_METH,
    PELEM_INT_SHAD_METH,
    PELEM_BACK_INT_SHAD_METH,
    PELEM_REFL_EQN,
    PELEM_BACK_REFL_EQN,
    PELEM_REFL_PROPS,
    PELEM_BACK_REFL_PROPS,
    PELEM_BACK_INT_STYLE,
    PELEM_BACK_INT_STYLE_IND,
    PELEM_FACE_DISTING_MODE,
    PELEM_FACE_CULL_MODE,
    PELEM_CURVE_APPROX_CRIT,
    PELEM_SURF_APPROX_CRIT,
    PELEM_PARA_SURF_CHARS,
    PELEM_LIGHT_SRC_STATE,
    PELEM_DCUE_IND,
    PELEM_COLR_MAP_IND,
    PELEM_FILL_AREA_SET3_DATA,
    PELEM_TRI_STRIP3_DATA,
    PELEM_QUAD_MESH3_DATA,
    PELEM_NUNI_BSP_CURVE,
    PELEM_NUNI_BSP_SURF,
    PELEM_POLYLINE_SET3_DATA,
    PELEM_CELL_ARRAY3_PLUS,
    PELEM_SET_OF_FILL_AREA_SET3_DATA,
    PELEM_RENDERING_COLR_MODEL
} Pelem_type;
#define PFIRST_PHIGS_ELEM PELEM_POLYLINE3
#define PLAST_PHIGS_ELEM PELEM_PICK_ID

typedef struct {
    Pint num_elem_types;
    Pelem_type* elem_types;
} Pelem_type_list;
typedef struct {
    Pint struct_id;
    Pint elem_pos;
} Pelem_ref;
typedef struct {
    Pint num_elem_refs;
    Pelem_ref* elem_refs;
} Pelem_ref_list;
typedef struct {
    Pint num_elem_ref_lists;
    Pelem_ref_list* elem_ref_lists;
} Pelem_ref_list_list;
typedef struct {
    Pint ar_id;
    char* name;
} Par_file;
typedef struct {
    Pint num_ar_files;
    Par_file* ar_files;
} Par_file_list;
typedef struct {
    Plimit win;
    Plimit proj_vp;
} Pview_map;
typedef struct {
    Plimit win;
    Plimit3 proj_vp;
    Pproj_type proj_type;
    Ppoint3 proj_ref_point;
    Pfloat view_plane;
    Pfloat back_plane;
    Pfloat front_plane;
} Pview_map3;
/* A colour's three components in one of the colour models; each member is three Pfloats at the
 * same places, so any member reads the components of any model. */
typedef struct {
    Pfloat red, green, blue;
} Prgb;
typedef struct {
    Pfloat cieluv_x, cieluv_y, cieluv_y_lum;
} Pcieluv;
typedef struct {
    Pfloat hue, lightness, satur;
} Phls;
typedef struct {
    Pfloat hue, satur, value;
} Phsv;
typedef union {
    Prgb rgb;
    Pcieluv cieluv;
    Phls hls;
    Phsv hsv;
    Pdata unsupp;
} Pcolr_rep;
/* A general colour (PHIGS PLUS): an index, or a direct colour whose x, y, z are the components
 * in colour model `type` (PMODEL_RGB: red, green, blue; PMODEL_CIELUV: u', v', Y; PMODEL_HSV:
 * hue, saturation, value; PMODEL_HLS: hue, lightness, saturation; see pset_colr_model). */
typedef struct {
    Pint type; /* PINDIRECT or PMODEL_RGB .. PMODEL_HLS */
    union {
        Pint ind;
        struct {
            Pfloat x, y, z;
        } general;
    } val;
} Pgcolr;
#define PINDIRECT 0
#define PMODEL_RGB 1

/* ---- PHIGS PLUS element data (attributes and NURBS primitives; see the PHIGS PLUS part below) */
typedef enum { PDISTING_NO, PDISTING_YES } Pdisting_mode;
typedef enum { PCULL_NONE, PCULL_BACKFACE, PCULL_FRONTFACE } Pcull_mode;
/* Curve and surface approximation criteria this implementation draws. */
#define PCURV_WS_DEP 1
#define PCURV_CONST_PARAM_SUBDIV_BETWEEN_KNOTS 2
#define PCURV_CHORDAL_DEVIATION_WC 6
#define PSURF_WS_DEP 1
#define PSURF_CONST_PARAM_SUBDIV_BETWEEN_KNOTS 2
#define PSURF_CHORDAL_DEVIATION_WC 6
/* Parametric surface characteristics: none, workstation dependent, iso-parametric curves, level
 * curves in modelling (4) or world (5) coordinates: the surface cut by the planes through
 * origin + t * direction perpendicular to direction, one per t in params, drawn with the
 * polyline attributes as iso-parametric curves are. A zero direction or a value that is not
 * finite is -202. */
#define PSC_NONE 1
#define PSC_WS_DEP 2
#define PSC_ISOPARAMETRIC_CURVES 3
#define PSC_LEVEL_CURVES_MC 4
#define PSC_LEVEL_CURVES_WC 5
typedef struct {
    Pint num_floats;
    Pfloat* floats;
} Pfloat_list;
typedef enum { PCP_UNIFORM, PCP_NON_UNIFORM } Pcurve_placement;
typedef union {
    struct {
        Pint unused;
    } psc_1;
    struct {
        Pint unused;
    } psc_2;
    struct {
        /* PCP_UNIFORM: u_count curves of constant u evenly over the domain (v_count alike);
           PCP_NON_UNIFORM: one at each interior knot and u_count evenly inside each knot span.
           Drawn along the nearest rows of the tessellation grid. */
        Pcurve_placement placement;
        Pint u_count;
        Pint v_count;
    } psc_3;
    struct {
        Ppoint3 origin;
        Pvec3 direction;
        Pfloat_list params;
    } psc_4;
    struct {
        Ppoint3 origin;
        Pvec3 direction;
        Pfloat_list params;
    } psc_5;
} Ppara_surf_characs;
typedef struct {
    Pfloat ambient_coef;
    Pfloat diffuse_coef;
    Pfloat specular_coef;
    Pgcolr specular_colr;
    Pfloat specular_exp;
    Pfloat transpar_coef;
} Prefl_props;
typedef struct {
    Pint type;
    Pfloat value;
} Pcurv_approx;
typedef struct {
    Pint type;
    Pfloat u_val, v_val;
} Psurf_approx;

typedef enum { PRATIONAL, PNON_RATIONAL } Prational;
typedef struct {
    Pfloat x, y, z, w;
} Ppoint4;
typedef struct {
    Pint num_points;
    Ppoint4* points;
} Ppoint_list4;
typedef union {
    Ppoint_list3 point3d; /* PNON_RATIONAL */
    Ppoint_list4 point4d; /* PRATIONAL */
} Ppoint_list34;
typedef union {
    Ppoint_list point2d;  /* PNON_RATIONAL */
    Ppoint_list3 point3d; /* PRATIONAL */
} Ppoint_list23;
typedef struct {
    Pint_size num_points;
    union {
        Ppoint3* point3d;
        Ppoint4* point4d;
    } points;
} Ppoint_grid34;
typedef struct {
    Pedge_flag visible;
    Prational rationality;
    Pint order;
    Pint approx_type;
    Pfloat approx_val;
    Pfloat_list knots;
    Pfloat tmin, tmax;
    Ppoint_list23 cpts;
} Ptrimcurve;
typedef struct {
    Pint num_curves;
    Ptrimcurve* curves;
} Ptrimcurve_list;
/* Primitives with data (PHIGS PLUS): which data the facets, edges and vertices carry. A colour
 * value is an index (colr_type PINDIRECT) or direct in a colour model (PMODEL_RGB .. PMODEL_HLS), the same
 * for every vertex and facet of one primitive. */
#define PFACET_NONE 0
#define PFACET_COLOUR 1
#define PFACET_NORMAL 2
#define PFACET_COLOUR_NORMAL 3
#define PEDGE_NONE 0
#define PEDGE_VISIBILITY 1
#define PVERT_COORD 0
#define PVERT_COORD_COLOUR 1
#define PVERT_COORD_NORMAL 2
#define PVERT_COORD_COLOUR_NORMAL 3
typedef union {
    Pint ind;
    Pcolr_rep direct; /* the components in the primitive's colour model (any member reads them) */
} Pcoval;
typedef struct {
    Pcoval colr;
    Pvec3 norm;
} Pconorm3;
typedef union {
    Pcoval colr;
    Pvec3 norm;
    Pconorm3 conorm;
} Pfacet_data3;
typedef union {
    Pcoval* colrs;
    Pvec3* norms;
    Pconorm3* conorms;
} Pfacet_data_arr3;
typedef struct {
    Ppoint3 point;
    Pcoval colr;
} Pptco3;
typedef struct {
    Ppoint3 point;
    Pvec3 norm;
} Pptnorm3;
typedef struct {
    Ppoint3 point;
    Pcoval colr;
    Pvec3 norm;
} Pptconorm3;
typedef union {
    Ppoint3* points;
    Pptco3* ptcolrs;
    Pptnorm3* ptnorms;
    Pptconorm3* ptconorms;
} Pfacet_vdata_arr3;
typedef struct {
    Pint num_vertices;
    Pfacet_vdata_arr3 vertex_data;
} Pfacet_vdata_list3;
typedef struct {
    Pint num_edges;
    Pedge_flag* edgedata;
} Pedge_data_list;
/* ---- PHIGS PLUS polyline sets and sets of fill area sets (the element data of the PHIGS PLUS
 * primitives section near the end). */
typedef union {
    Ppoint3* points; /* PVERT_COORD */
    Pptco3* ptcolrs; /* PVERT_COORD_COLOUR */
} Pline_vdata_arr3;
typedef struct {
    Pint num_vertices;
    Pline_vdata_arr3 vertex_data;
} Pline_vdata_list3;
typedef struct {
    Pint num_lists;
    Pedge_data_list* edgelist;
} Pedge_data_list_list;
typedef struct {
    Pint num_lists;
    Pint_list* lists;
} Pint_list_list;

/* The contents of an element (INQUIRE (CURRENT) ELEMENT CONTENT). Every pointer in it points
 * into the Pstore the inquiry was given, valid until that store's next use or deletion. */
typedef union {
    Pint int_data;
    Pfloat float_data;
    Ppoint_list3 point_list3;
    Ppoint_list point_list;
    Ppoint_list_list3 point_list_list3;
    Ppoint_list_list point_list_list;
    struct {
        Ppoint3 pos;
        Pvec3 dir[2];
        char* char_string;
    } text3;
    struct {
        Ppoint pos;
        char* char_string;
    } text;
    struct {
        Ppoint3 ref_point;
        Pvec3 offset;
        char* char_string;
    } anno_text_rel3;
    struct {
        Ppoint ref_point;
        Pvec offset;
        char* char_string;
    } anno_text_rel;
    struct {
        Pparal paral;
        Ppat_rep colr_array;
    } cell_array3;
    struct {
        Prect rect;
        Ppat_rep colr_array;
    } cell_array;
    Ptext_prec text_prec;
    Pvec char_up_vec;
    Ptext_path text_path;
    Ptext_align text_align;
    Pint_style int_style;
    Pedge_flag edge_flag;
    Pfloat_size pat_size;
    struct {
        Ppoint3 ref_point;
        Pvec3 ref_vec[2];
    } pat_ref_point_vecs;
    Ppoint pat_ref_point;
    Pint_list names;
    struct {
        Paspect id;
        Pasf source;
    } asf;
    struct {
        Pcompose_type compose_type;
        Pmatrix3 matrix;
    } local_tran3;
    struct {
        Pcompose_type compose_type;
        Pmatrix matrix;
    } local_tran;
    Pmatrix3 global_tran3;
    Pmatrix global_tran;
    struct {
        Pint op;
        Phalf_space_list3 half_spaces;
    } model_clip3;
    struct {
        Pint op;
        Phalf_space_list half_spaces;
    } model_clip;
    Pclip_ind clip_ind;
    Pdata appl_data;
    Pgcolr colr;
    struct {
        Pint id;
        Ppoint_list3 point_list;
        Pgdp_data3 data;
    } gdp3;
    struct {
        Pint id;
        Ppoint_list point_list;
        Pgdp_data data;
    } gdp;
    struct {
        Pint id;
        Pgse_data data;
    } gse;
    /* PHIGS PLUS: shading methods, reflectance equations, depth cue and colour mapping indices
     * answer int_data, back interior style int_style, back interior colour colr / int_data. */
    Prefl_props props;
    Pcurv_approx curv_approx;
    Psurf_approx surf_approx;
    struct {
        Pint type;
        Ppara_surf_characs data;
    } para_surf_characs;
    struct {
        Pint_list activation;
        Pint_list deactivation;
    } lss;
    Pdisting_mode disting_mode;
    Pcull_mode cull_mode;
    struct {
        Pint order;
        Pfloat_list knots;
        Prational rationality;
        Ppoint_list34 cpts;
        Pfloat min, max;
    } nuni_bsp_curv;
    struct {
        Pint u_order, v_order;
        Pfloat_list uknots, vknots;
        Prational rationality;
        Ppoint_grid34 grid;
        Pint num_trim_loops;
        Ptrimcurve_list* trim_loops;
    } nuni_bsp_surf;
    struct {
        Pint fflag, eflag, vflag, colr_type;
        Pfacet_data3 fdata;
        Pint nfa;
        Pedge_data_list* edata; /* one list per contour with PEDGE_VISIBILITY, else NULL */
        Pfacet_vdata_list3* vdata;
    } fas3_data;
    struct {
        Pint fflag, vflag, colr_type, nv;
        Pfacet_data_arr3 fdata;
        Pfacet_vdata_arr3 vdata;
    } tri_strip3;
    struct {
        Pint fflag, vflag, colr_type;
        Pint_size dim;
        Pfacet_data_arr3 fdata;
        Pfacet_vdata_arr3 vdata;
    } quad_mesh3;
    /* PHIGS PLUS: polyline set, cell array plus, set of fill area sets (rendering colour model:
     * int_data) */
    struct {
        Pint vflag, colr_type, npl;
        Pline_vdata_list3* vdata;
    } plsd3;
    struct {
        Pparal paral;
        Pint_size dims;
        Pint colr_type;
        Pcoval* colr_array; /* dims.size_x x dims.size_y, row by row */
    } cell_array_plus;
    struct {
        Pint fflag, eflag, vflag, colr_type, num_sets;
        Pfacet_data_arr3 fdata;      /* one per set */
        Pedge_data_list_list* edata; /* one per set; NULL without edge data */
        Pint_list_list* vlist;       /* one per set: its contours' vertex indices */
        Pfacet_vdata_list3 vdata;    /* the vertices */
    } sofas3;
} Pelem_data;

/* A Store: the memory an inquiry with a variable-size answer fills (ISO 9593-4). */
typedef struct Phigs_store* Pstore;

/* ---- workstations: types, states and tables */
typedef enum { PWS_ST_WSCL, PWS_ST_WSOP } Pws_st;
typedef enum { PCAT_OUT, PCAT_IN, PCAT_OUTIN, PCAT_MO, PCAT_MI } Pws_cat;
/* The attribute sets a GDP uses (pinq_gdp, pinq_gdp3). */
typedef enum { PATTR_LINE, PATTR_MARKER, PATTR_TEXT, PATTR_INT, PATTR_EDGE } Pattrs;
typedef enum { PWS_INDEP, PWS_DEP } Pws_dep_ind;
typedef struct {
    Pint id;
    Pws_dep_ind ind;
} Pgse_id_dep;
typedef struct {
    Pint num_id_facs;
    Pgse_id_dep* id_facs;
} Pgse_id_dep_list;
typedef enum { PFLAG_POSTPONE, PFLAG_PERFORM } Pregen_flag;
typedef enum { PFLAG_COND, PFLAG_ALWAYS } Pctrl_flag;
typedef struct {
    Pint id;
    Pfloat disp_pri;
} Pposted_struct;
typedef struct {
    Pint num_postings;
    Pposted_struct* postings;
} Pposted_struct_list;
typedef struct {
    Pmatrix3 ori_matrix; /* world coordinates -> view reference coordinates */
    Pmatrix3 map_matrix; /* view reference coordinates -> NPC */
    Plimit3 clip_limit;  /* NPC */
    Pclip_ind xy_clip, back_clip, front_clip;
} Pview_rep3;
typedef struct {
    Pmatrix ori_matrix;
    Pmatrix map_matrix;
    Plimit clip_limit;
    Pclip_ind xy_clip;
} Pview_rep;

/* The workstation types of this implementation (pinq_list_avail_ws_types lists them and
 * pinq_ws_cat answers their category). The connection identifier popen_ws takes is a
 * NUL-terminated string whose meaning depends on the type:
 *   PWST_OFFSCREEN  OUTIN, a Vulkan image drawn by lavapipe, needing no display: NULL, or the
 *                   name of a PNG file written at every pupd_ws/predraw_all_structs and at
 *                   pclose_ws;
 *   PWST_WINDOW     OUTIN, a window of its own: NULL ($DISPLAY) or an X display name;
 *   PWST_PNG        OUTPUT, raster hardcopy: the PNG file name (required, error 50 without);
 *   PWST_PDF, PWST_SVG, PWST_EPS  OUTPUT, vector hardcopy (every primitive a vector path, A4
 *                   landscape, device units are points): the file name (required, error 50),
 *                   rewritten at every update and complete at pclose_ws.
 * The Vulkan types read PHIGS_VK_DEVICE=lavapipe|hardware (default lavapipe) and
 * PHIGS_VK_VALIDATION=1 (validation layer on, every message printed to stderr). */
#define PWST_OFFSCREEN 1
#define PWST_WINDOW 2
#define PWST_PNG 3
#define PWST_PDF 4
#define PWST_SVG 5
#define PWST_EPS 6
/* The specific workstation types (the standard's generic and specific pair): every open
 * workstation has one of its own, PWST_SPECIFIC_BASE or above, answered by pinq_ws_conn_type and
 * never reused. Every function that takes a workstation type takes it while the workstation is
 * open and answers from that workstation's description table as it is now (a resized window's
 * pinq_disp_space_size3); popen_ws opens its generic type. Closed, it is error 52. */
#define PWST_SPECIFIC_BASE 4096

/* ISO function identifiers (the error handler's func_num): macros, as the binding defines them. */
#define Pfn_open_phigs (0)
#define Pfn_close_phigs (1)
#define Pfn_open_ws (2)
#define Pfn_close_ws (3)
#define Pfn_redraw_all_structs (4)
#define Pfn_upd_ws (5)
#define Pfn_message (7)
#define Pfn_polyline3 (8)
#define Pfn_polyline (9)
#define Pfn_polymarker3 (10)
#define Pfn_polymarker (11)
#define Pfn_text3 (12)
#define Pfn_text (13)
#define Pfn_anno_text_rel3 (14)
#define Pfn_anno_text_rel (15)
#define Pfn_fill_area3 (16)
#define Pfn_fill_area (17)
#define Pfn_fill_area_set3 (18)
#define Pfn_fill_area_set (19)
#define Pfn_cell_array3 (20)
#define Pfn_cell_array (21)
#define Pfn_gdp3 (22)
#define Pfn_gdp (23)
#define Pfn_set_line_ind (24)
#define Pfn_set_marker_ind (25)
#define Pfn_set_text_ind (26)
#define Pfn_set_int_ind (27)
#define Pfn_set_edge_ind (28)
#define Pfn_set_linetype (29)
#define Pfn_set_linewidth (30)
#define Pfn_set_line_colr_ind (31)
#define Pfn_set_marker_type (32)
#define Pfn_set_marker_size (33)
#define Pfn_set_marker_colr_ind (34)
#define Pfn_set_text_font (35)
#define Pfn_set_text_prec (36)
#define Pfn_set_char_expan (37)
#define Pfn_set_char_space (38)
#define Pfn_set_text_colr_ind (39)
#define Pfn_set_char_ht (40)
#define Pfn_set_char_up_vec (41)
#define Pfn_set_text_path (42)
#define Pfn_set_text_align (43)
#define Pfn_set_anno_char_ht (44)
#define Pfn_set_anno_char_up_vec (45)
#define Pfn_set_anno_path (46)
#define Pfn_set_anno_align (47)
#define Pfn_set_anno_style (48)
#define Pfn_set_int_style (49)
#define Pfn_set_int_style_ind (50)
#define Pfn_set_int_colr_ind (51)
#define Pfn_set_edge_flag (52)
#define Pfn_set_edgetype (53)
#define Pfn_set_edgewidth (54)
#define Pfn_set_edge_colr_ind (55)
#define Pfn_set_pat_size (56)
#define Pfn_set_pat_ref_point_vecs (57)
#define Pfn_set_pat_ref_point (58)
#define Pfn_add_names_set (59)
#define Pfn_remove_names_set (60)
#define Pfn_set_indiv_asf (61)
#define Pfn_set_hlhsr_id (72)
#define Pfn_set_local_tran3 (74)
#define Pfn_set_local_tran (75)
#define Pfn_set_global_tran3 (76)
#define Pfn_set_global_tran (77)
#define Pfn_set_model_clip_vol3 (78)
#define Pfn_set_model_clip_vol (79)
#define Pfn_set_model_clip_ind (80)
#define Pfn_restore_model_clip_vol (81)
#define Pfn_set_view_ind (82)
#define Pfn_set_view_rep3 (83)
#define Pfn_set_view_rep (84)
#define Pfn_set_ws_win3 (86)
#define Pfn_set_ws_win (87)
#define Pfn_set_ws_vp3 (88)
#define Pfn_set_ws_vp (89)
#define Pfn_open_struct (90)
#define Pfn_close_struct (91)
#define Pfn_exec_struct (92)
#define Pfn_label (93)
#define Pfn_appl_data (94)
#define Pfn_gse (95)
#define Pfn_set_edit_mode (96)
#define Pfn_copy_all_elems_struct (97)
#define Pfn_set_elem_ptr (98)
#define Pfn_offset_elem_ptr (99)
#define Pfn_set_elem_ptr_label (100)
#define Pfn_del_elem (101)
#define Pfn_del_elem_range (102)
#define Pfn_del_elems_labels (103)
#define Pfn_empty_struct (104)
#define Pfn_del_struct (105)
#define Pfn_del_struct_net (106)
#define Pfn_del_all_structs (107)
#define Pfn_change_struct_id (108)
#define Pfn_change_struct_refs (109)
#define Pfn_change_struct_id_refs (110)
#define Pfn_open_ar_file (114)
#define Pfn_close_ar_file (115)
#define Pfn_ar_structs (116)
#define Pfn_ar_struct_nets (117)
#define Pfn_ar_all_structs (118)
#define Pfn_set_conf_res (119)
#define Pfn_ret_struct_ids (120)
#define Pfn_ret_structs (121)
#define Pfn_ret_struct_nets (122)
#define Pfn_ret_all_structs (123)
#define Pfn_ret_paths_ances (124)
#define Pfn_ret_paths_descs (125)
#define Pfn_del_structs_ar (126)
#define Pfn_del_struct_nets_ar (127)
#define Pfn_del_all_structs_ar (128)
#define Pfn_post_struct (111)
#define Pfn_unpost_struct (112)
#define Pfn_unpost_all_structs (113)
#define Pfn_set_pick_id (129)
#define Pfn_set_err_hand_mode (179)
#define Pfn_escape (180)
#define Pfn_set_err_hand (181)
#define Pfn_line_colr (310)
#define Pfn_marker_colr (312)
#define Pfn_text_colr (313)
#define Pfn_int_colr (316)
#define Pfn_edge_colr (327)
#define Pfn_set_line_colr Pfn_line_colr
#define Pfn_set_marker_colr Pfn_marker_colr
#define Pfn_set_text_colr Pfn_text_colr
#define Pfn_set_int_colr Pfn_int_colr
#define Pfn_set_edge_colr Pfn_edge_colr

/* ---- control */
void popen_phigs(const char* err_file, size_t mem_units);
void pclose_phigs(void);
void pemergency_close_phigs(void);
void pinq_sys_st(Psys_st* sys_st);
/* MESSAGE: needs the workstation open (errors 3, 54); the message goes to the error file
 * (stderr without one) as the line "MESSAGE <ws_id>: <message>". */
void pescape(Pint func_id, const Pescape_in_data* in_data, Pstore store, Pescape_out_data** out_data);
void pmessage(Pint ws_id, const char* message);
/* The PHIGS description table: this implementation sets no limit on open workstations, open
 * archive files, names in name sets or filter lengths (INT_MAX each) and lists no character
 * set beyond the ISO 646 one every implementation has (an empty list). */
void pinq_phigs_facs(Pint num_elems_appl_list, Pint start_ind, Pint* err_ind, Pint* max_open_ws,
                     Pint* max_open_ar, Pint* num_names, Pint_list* char_sets, Pint* num_elems_impl_list,
                     Pint* max_norm_filter_list, Pint* max_inv_filter_list);

/* ---- error handling */
void perr_hand(Pint err_num, Pint func_num, const char* err_file);
void perr_log(Pint err_num, Pint func_num, const char* err_file);
void pset_err_hand(void (*new_err_hand)(Pint, Pint, const char*),
                   void (**old_err_hand)(Pint, Pint, const char*));
void pset_err_hand_mode(Perr_mode mode);
void pinq_err_hand_mode(Pint* err_ind, Perr_mode* mode);

/* ---- stores */
void pcreate_store(Pint* err_ind, Pstore* store);
void pdel_store(Pstore store);

/* ---- structures */
void popen_struct(Pint struct_id);
void pclose_struct(void);
void pset_edit_mode(Pedit_mode mode);
void pset_elem_ptr(Pint elem_ptr_value);
void poffset_elem_ptr(Pint elem_ptr_offset);
void pset_elem_ptr_label(Pint label_id);
void pdel_elem(void);
void pdel_elem_range(Pint elem_ptr1_value, Pint elem_ptr2_value);
void pdel_elems_labels(Pint label1_id, Pint label2_id);
void pempty_struct(Pint struct_id);
void pdel_struct(Pint struct_id);
void pdel_struct_net(Pint struct_id, Pref_flag ref_flag);
void pdel_all_structs(void);
void pcopy_all_elems_struct(Pint struct_id);
void pchange_struct_id(Pint orig_struct_id, Pint result_struct_id);
void pchange_struct_refs(Pint orig_struct_id, Pint result_struct_id);
void pchange_struct_id_refs(Pint orig_struct_id, Pint result_struct_id);

/* ---- output primitives */
void ppolyline3(const Ppoint_list3* point_list);
void ppolyline(const Ppoint_list* point_list);
void ppolymarker3(const Ppoint_list3* point_list);
void ppolymarker(const Ppoint_list* point_list);
void ptext3(const Ppoint3* text_pos, const Pvec3 text_dir[2], const char* char_string);
void ptext(const Ppoint* text_pos, const char* char_string);
void panno_text_rel3(const Ppoint3* ref_point, const Pvec3* offset, const char* char_string);
void panno_text_rel(const Ppoint* ref_point, const Pvec* offset, const char* char_string);
void pfill_area3(const Ppoint_list3* point_list);
void pfill_area(const Ppoint_list* point_list);
void pfill_area_set3(const Ppoint_list_list3* point_list_list);
void pfill_area_set(const Ppoint_list_list* point_list_list);
void pcell_array3(const Pparal* paral, const Ppat_rep* colr_array);
void pcell_array(const Prect* rect, const Ppat_rep* colr_array);

/* ---- attributes */
void pset_line_ind(Pint line_ind);
void pset_marker_ind(Pint marker_ind);
void pset_text_ind(Pint text_ind);
void pset_int_ind(Pint int_ind);
void pset_edge_ind(Pint edge_ind);
void pset_linetype(Pint linetype);
void pset_linewidth(Pfloat linewidth);
void pset_line_colr_ind(Pint colr_ind);
void pset_marker_type(Pint marker_type);
void pset_marker_size(Pfloat marker_size);
void pset_marker_colr_ind(Pint colr_ind);
void pset_text_font(Pint font);
void pset_text_prec(Ptext_prec prec);
void pset_char_expan(Pfloat char_expan);
void pset_char_space(Pfloat char_space);
void pset_text_colr_ind(Pint colr_ind);
void pset_char_ht(Pfloat char_ht);
void pset_char_up_vec(const Pvec* char_up_vec);
void pset_text_path(Ptext_path text_path);
void pset_text_align(const Ptext_align* text_align);
void pset_anno_char_ht(Pfloat char_ht);
void pset_anno_char_up_vec(const Pvec* char_up_vec);
void pset_anno_path(Ptext_path text_path);
void pset_anno_align(const Ptext_align* text_align);
void pset_anno_style(Pint anno_style);
void pset_int_style(Pint_style int_style);
void pset_int_style_ind(Pint int_style_ind);
void pset_int_colr_ind(Pint colr_ind);
void pset_edge_flag(Pedge_flag edge_flag);
void pset_edgetype(Pint edgetype);
void pset_edgewidth(Pfloat edgewidth);
void pset_edge_colr_ind(Pint colr_ind);
/* Pattern size, reference point and vectors (modelling coordinates): where the cells of an
 * interior of style PATTERN lie; a zero size component or parallel vectors change nothing. */
void pset_pat_size(const Pfloat_size* pat_size);
void pset_pat_ref_point(const Ppoint* ref_point);
void pset_pat_ref_point_vecs(const Ppoint3* ref_point, const Pvec3 ref_vec[2]);
void pset_line_colr(const Pgcolr* colr);
void pset_marker_colr(const Pgcolr* colr);
void pset_text_colr(const Pgcolr* colr);
void pset_int_colr(const Pgcolr* colr);
void pset_edge_colr(const Pgcolr* colr);
void pset_indiv_asf(Paspect asf_id, Pasf asf_source);
void padd_names_set(const Pint_list* names);
void premove_names_set(const Pint_list* names);
void pset_local_tran3(Pmatrix3 local_tran, Pcompose_type compose_type);
void pset_local_tran(Pmatrix local_tran, Pcompose_type compose_type);
void pset_global_tran3(Pmatrix3 global_tran);
void pset_global_tran(Pmatrix global_tran);
void pset_model_clip_vol3(Pint op, const Phalf_space_list3* half_spaces);
void pset_model_clip_vol(Pint op, const Phalf_space_list* half_spaces);
void pset_model_clip_ind(Pclip_ind clip_ind);
void prestore_model_clip_vol(void);
void pset_view_ind(Pint view_ind);
void pset_hlhsr_id(Pint hlhsr_id);
void pset_pick_id(Pint pick_id);
void pexec_struct(Pint struct_id);
void plabel(Pint label_id);
void pappl_data(const Pdata* data);
void pgdp3(const Ppoint_list3* point_list, Pint gdp3_id, const Pgdp_data3* gdp_data);
void pgdp(const Ppoint_list* point_list, Pint gdp_id, const Pgdp_data* gdp_data);
void pgse(Pint id, const Pgse_data* gse_data);

/* ---- archives */
void popen_ar_file(Pint ar_id, const char* ar_file);
void pclose_ar_file(Pint ar_id);
void par_structs(Pint ar_id, const Pint_list* struct_ids);
void par_struct_nets(Pint ar_id, const Pint_list* struct_ids);
void par_all_structs(Pint ar_id);
void pset_conf_res(Pconf_res archive_res, Pconf_res retrieve_res);
void pret_struct_ids(Pint ar_id, Pint num_elems_appl_list, Pint start_ind, Pint_list* ids,
                     Pint* num_elems_impl_list);
void pret_structs(Pint ar_id, const Pint_list* struct_ids);
void pret_struct_nets(Pint ar_id, const Pint_list* struct_ids);
void pret_all_structs(Pint ar_id);
void pret_paths_ances(Pint ar_id, Pint struct_id, Ppath_order order, Pint depth, Pstore store,
                      Pelem_ref_list_list** paths);
void pret_paths_descs(Pint ar_id, Pint struct_id, Ppath_order order, Pint depth, Pstore store,
                      Pelem_ref_list_list** paths);
void pdel_structs_ar(Pint ar_id, const Pint_list* struct_ids);
void pdel_struct_nets_ar(Pint ar_id, const Pint_list* struct_ids);
void pdel_all_structs_ar(Pint ar_id);

/* ---- transformation utilities (error indicator 2 while PHIGS is closed) */
void ptranslate3(const Pvec3* trans_vector, Pint* err_ind, Pmatrix3 tran_matrix);
void ptranslate(const Pvec* trans_vector, Pint* err_ind, Pmatrix tran_matrix);
void pscale3(const Pvec3* scale_vector, Pint* err_ind, Pmatrix3 tran_matrix);
void pscale(const Pvec* scale_vector, Pint* err_ind, Pmatrix tran_matrix);
void protate_x(Pfloat angle, Pint* err_ind, Pmatrix3 tran_matrix);
void protate_y(Pfloat angle, Pint* err_ind, Pmatrix3 tran_matrix);
void protate_z(Pfloat angle, Pint* err_ind, Pmatrix3 tran_matrix);
void protate(Pfloat angle, Pint* err_ind, Pmatrix tran_matrix);
void pcompose_matrix3(Pmatrix3 mat_a, Pmatrix3 mat_b, Pint* err_ind, Pmatrix3 mat_comp);
void pcompose_matrix(Pmatrix mat_a, Pmatrix mat_b, Pint* err_ind, Pmatrix mat_comp);
void ptran_point3(const Ppoint3* point, Pmatrix3 tran_matrix, Pint* err_ind, Ppoint3* result);
void ptran_point(const Ppoint* point, Pmatrix tran_matrix, Pint* err_ind, Ppoint* result);
void pbuild_tran_matrix3(const Ppoint3* point, const Pvec3* shift_vec, Pfloat x_angle, Pfloat y_angle,
                         Pfloat z_angle, const Pvec3* scale_vec, Pint* err_ind, Pmatrix3 tran_matrix);
void pbuild_tran_matrix(const Ppoint* point, const Pvec* shift_vec, Pfloat angle, const Pvec* scale_vec,
                        Pint* err_ind, Pmatrix tran_matrix);
void pcompose_tran_matrix3(Pmatrix3 matrix, const Ppoint3* point, const Pvec3* shift_vec, Pfloat x_angle,
                           Pfloat y_angle, Pfloat z_angle, const Pvec3* scale_vec, Pint* err_ind,
                           Pmatrix3 tran_matrix);
void pcompose_tran_matrix(Pmatrix matrix, const Ppoint* point, const Pvec* shift_vec, Pfloat angle,
                          const Pvec* scale_vec, Pint* err_ind, Pmatrix tran_matrix);
void peval_view_ori_matrix3(const Ppoint3* vrp, const Pvec3* vpn, const Pvec3* vup, Pint* err_ind,
                            Pmatrix3 view_ori_matrix);
void peval_view_ori_matrix(const Ppoint* vrp, const Pvec* vup, Pint* err_ind, Pmatrix view_ori_matrix);
void peval_view_map_matrix3(const Pview_map3* map, Pint* err_ind, Pmatrix3 view_map_matrix);
void peval_view_map_matrix(const Pview_map* map, Pint* err_ind, Pmatrix view_map_matrix);

/* ---- workstations (errors 3: no workstation open, 54: this one not open) */
/* OPEN WORKSTATION: errors 2, 52 (type not one of PWST_*), 53 (identifier in use), 50 (the type
 * needs a file name and conn_id is NULL or empty), 55 (the target could not be made, e.g. no
 * Vulkan device or no display). conn_id: see PWST_* above. */
void popen_ws(Pint ws_id, const void* conn_id, Pint ws_type);
/* CLOSE WORKSTATION: a file type writes its last picture first (903 when that fails). */
void pclose_ws(Pint ws_id);
/* POST STRUCTURE: priority in [0, 1] (208); a structure that does not exist is created empty. */
void ppost_struct(Pint ws_id, Pint struct_id, Pfloat priority);
void punpost_struct(Pint ws_id, Pint struct_id);
void punpost_all_structs(Pint ws_id);
/* REDRAW ALL STRUCTURES and UPDATE WORKSTATION (PERFORM) draw the picture on the target. */
void predraw_all_structs(Pint ws_id, Pctrl_flag ctrl_flag);
void pupd_ws(Pint ws_id, Pregen_flag regen_flag);
/* Workstation window (NPC: 151, 156) and viewport (device coordinates: 152, 157); the 2D forms
 * keep z. */
void pset_ws_win3(Pint ws_id, const Plimit3* ws_win_lim);
void pset_ws_win(Pint ws_id, const Plimit* ws_win_lim);
void pset_ws_vp3(Pint ws_id, const Plimit3* ws_vp_lim);
void pset_ws_vp(Pint ws_id, const Plimit* ws_vp_lim);
/* SET VIEW REPRESENTATION: index >= 1 (115), table size 32 (150), NaN clip limits 153, a NaN
 * or infinite matrix entry -208; the 2D form clips z to [0, 1] with front and back clipping off. */
void pset_view_rep3(Pint ws_id, Pint view_ind, const Pview_rep3* view_rep);
void pset_view_rep(Pint ws_id, Pint view_ind, const Pview_rep* view_rep);

/* ---- inquiries: they never call the error handler; *err_ind is 0 or the error number */
void pinq_struct_st(Pstruct_st* struct_st);
void pinq_ar_st(Par_st* ar_st);
void pinq_open_struct(Pint* err_ind, Popen_struct_status* status, Pint* struct_id);
void pinq_elem_ptr(Pint* err_ind, Pint* elem_ptr_value);
void pinq_edit_mode(Pint* err_ind, Pedit_mode* edit_mode);
void pinq_cur_elem_type_size(Pint* err_ind, Pelem_type* elem_type, size_t* elem_size);
void pinq_cur_elem_content(Pstore store, Pint* err_ind, Pelem_data** elem_data);
void pinq_elem_type_size(Pint struct_id, Pint elem_num, Pint* err_ind, Pelem_type* elem_type,
                         size_t* elem_size);
void pinq_elem_content(Pint struct_id, Pint elem_num, Pstore store, Pint* err_ind, Pelem_data** elem_data);
void pinq_struct_status(Pint struct_id, Pint* err_ind, Pstruct_status* status);
void pinq_struct_ids(Pint num_elems_appl_list, Pint start_ind, Pint* err_ind, Pint_list* struct_ids,
                     Pint* num_elems_impl_list);
void pinq_paths_ances(Pint struct_id, Ppath_order order, Pint depth, Pstore store, Pint* err_ind,
                      Pelem_ref_list_list** paths);
void pinq_paths_descs(Pint struct_id, Ppath_order order, Pint depth, Pstore store, Pint* err_ind,
                      Pelem_ref_list_list** paths);
void pelem_search(Pint struct_id, Pint start_elem, Psearch_dir dir, const Pelem_type_list* incl,
                  const Pelem_type_list* excl, Pint* err_ind, Psearch_status* status, Pint* found_elem);
void pinq_ar_files(Pstore store, Pint* err_ind, Par_file_list** ar_files);
void pinq_conf_res(Pint* err_ind, Pconf_res* archive_res, Pconf_res* retrieve_res);
void pinq_all_conf_structs(Pint ar_id, Pint num_elems_appl_list, Pint start_ind, Pint* err_ind,
                           Pint_list* ids, Pint* num_elems_impl_list);
void pinq_conf_structs_net(Pint ar_id, Pint struct_id, Pstruct_net_source source, Pint num_elems_appl_list,
                           Pint start_ind, Pint* err_ind, Pint_list* ids, Pint* num_elems_impl_list);

/* Workstation inquiries. pinq_ws_conn_type answers the connection identifier popen_ws was
 * given (its characters, NULL for none; they live in the store) and the type. */
void pinq_ws_st(Pws_st* ws_state);
void pinq_open_wss(Pint num_elems_appl_list, Pint start_ind, Pint* err_ind, Pint_list* open_ws_ids,
                   Pint* num_elems_impl_list);
void pinq_ws_conn_type(Pint ws_id, Pstore store, Pint* err_ind, void** conn_id, Pint* ws_type);
void pinq_posted_structs(Pint ws_id, Pint num_elems_appl_list, Pint start_ind, Pint* err_ind,
                         Pposted_struct_list* posted_structs, Pint* num_elems_impl_list);
void pinq_list_avail_ws_types(Pint num_elems_appl_list, Pint start_ind, Pint* err_ind, Pint_list* ws_types,
                              Pint* num_elems_impl_list);
void pinq_ws_cat(Pint ws_type, Pint* err_ind, Pws_cat* ws_cat);
/* GDPs and GSEs of a workstation type: PGDP_CIRCLE and PGDP_ARC on every type, each using the
 * polyline attributes (error 64 for any other identifier); no GSE. */
void pinq_list_avail_gdp3(Pint ws_type, Pint length, Pint start, Pint* err_ind, Pint_list* gdps,
                          Pint* total_length);
void pinq_list_avail_gdp(Pint ws_type, Pint length, Pint start, Pint* err_ind, Pint_list* gdps,
                         Pint* total_length);
void pinq_gdp3(Pint ws_type, Pint gdp, Pint* err_ind, Pint* num_attrs, Pattrs attrs[5]);
void pinq_gdp(Pint ws_type, Pint gdp, Pint* err_ind, Pint* num_attrs, Pattrs attrs[5]);
void pinq_list_avail_gse(Pint ws_type, Pint length, Pint start, Pint* err_ind, Pint_list* gses,
                         Pint* total_length);
void pinq_gse_facs(Pint ws_type, Pint length, Pint start, Pint* err_ind, Pgse_id_dep_list* gses,
                   Pint* total_length);

/* ==== workstation state, representations and description tables ====
 * Deferral and modification modes with requested and current values, the bundle, pattern and
 * colour tables (SET and REALIZED values), the highlighting and invisibility filters, and the
 * workstation description table of each type. Inquiries answer 3 (no workstation open), 54
 * (this one not open) or 52 (no such workstation type) first. */
typedef enum { PDEFER_ASAP, PDEFER_BNIG, PDEFER_BNIL, PDEFER_ASTI, PDEFER_WAIT } Pdefer_mode;
typedef enum { PMODE_NIVE, PMODE_UWOR, PMODE_UQUM } Pmod_mode;
typedef enum { PSURF_NOT_EMPTY, PSURF_EMPTY } Pdisp_surf_empty;
typedef enum { PVISUAL_ST_CORRECT, PVISUAL_ST_DEFER, PVISUAL_ST_SIMULATED } Pvisual_st;
typedef enum { PUPD_NOT_PEND, PUPD_PEND } Pupd_st;
typedef enum { PINQ_SET, PINQ_REALIZED } Pinq_type;
typedef enum { PPRI_HIGHER, PPRI_LOWER } Prel_pri;
typedef enum { PCLASS_VEC, PCLASS_RASTER, PCLASS_OTHER } Pws_class;
typedef enum { PDC_METRES, PDC_OTHER } Pdc_units;
typedef enum { PAVAIL_MONOCHR, PAVAIL_COLR } Pcolr_avail;
typedef enum { PDYN_IRG, PDYN_IMM, PDYN_CBS } Pdyn_mod;
/* Colour models (pset_colr_model; every workstation type has all four, default RGB). Each has
 * three components in [0, 1]. RGB: linear, ITU-R BT.709 primaries. CIELUV: CIE 1976 chromaticity
 * u', v' and luminance Y relative to the reference white D65 (u' 0.1978, v' 0.4683), Y 1 being
 * RGB (1, 1, 1). HSV and HLS: hue a fraction of a turn (0 red, 1/3 green, 2/3 blue), as Foley,
 * van Dam, Feiner and Hughes, "Computer Graphics: Principles and Practice" (1990) give them. The
 * workstation's model says how pset_colr_rep's and pinq_colr_rep's Pcolr_rep are read: an entry
 * keeps the model it was given in (PINQ_SET answers it converted to the current model, exactly
 * when unchanged); it is drawn as RGB clamped to [0, 1] (PINQ_REALIZED: that RGB in the current
 * model). Direct general colours carry their own model. */
#define PMODEL_CIELUV 2
#define PMODEL_HSV 3
#define PMODEL_HLS 4
typedef struct {
    Pint_list incl_set;
    Pint_list excl_set;
} Pfilter;
typedef struct {
    Pint type;
    Pfloat width; /* linewidth scale factor */
    Pint colr_ind;
} Pline_bundle;
typedef struct {
    Pint type;
    Pfloat size; /* marker size scale factor */
    Pint colr_ind;
} Pmarker_bundle;
typedef struct {
    Pint font;
    Ptext_prec prec;
    Pfloat char_expan;
    Pfloat char_space;
    Pint colr_ind;
} Ptext_bundle;
typedef struct {
    Pint_style style;
    Pint style_ind;
    Pint colr_ind;
} Pint_bundle;
typedef struct {
    Pedge_flag flag;
    Pint type;
    Pfloat width; /* edgewidth scale factor */
    Pint colr_ind;
} Pedge_bundle;
typedef struct {
    Pint_list types;
    Pint num_widths; /* 0: continuous */
    Pfloat nom_width, min_width, max_width;
    Pint num_pred_inds;
} Pline_facs;
typedef struct {
    Pint_list types;
    Pint num_sizes; /* 0: continuous */
    Pfloat nom_size, min_size, max_size;
    Pint num_pred_inds;
} Pmarker_facs;
typedef struct {
    Pint font;
    Ptext_prec prec;
} Ptext_font_prec;
typedef struct {
    Pint num_font_precs;
    Ptext_font_prec* font_precs;
    Pint num_char_hts; /* 0: continuous */
    Pfloat min_char_ht, max_char_ht;
    Pint num_char_expans; /* 0: continuous */
    Pfloat min_char_expan, max_char_expan;
    Pint num_pred_inds;
} Ptext_facs;
typedef struct {
    Pint num_int_styles;
    Pint_style int_styles[5];
    Pint_list hatch_styles;
    Pint num_pred_inds;
} Pint_facs;
typedef struct {
    Pint_list types;
    Pint num_widths; /* 0: continuous */
    Pfloat nom_width, min_width, max_width;
    Pint num_pred_inds;
} Pedge_facs;
typedef struct {
    Pint num_colrs; /* 0: continuous */
    Pcolr_avail colr_avail;
    Pint num_pred_inds;
} Pcolr_facs;
typedef struct {
    Pfloat size_x, size_y, size_z;
} Pfloat_size3;
typedef struct {
    Pint size_x, size_y, size_z;
} Pint_size3;
typedef struct {
    Pdc_units dc_units;
    Pfloat_size size_dc;
    Pint_size size_raster;
} Pdisp_space_size;
typedef struct {
    Pdc_units dc_units;
    Pfloat_size3 size_dc;
    Pint_size3 size_raster;
} Pdisp_space_size3;
typedef struct {
    Pint line_bundles, mark_bundles, text_bundles, int_bundles, edge_bundles, pat_reps, colr_reps, view_reps;
} Pws_tables;
typedef struct {
    Pdyn_mod line_bundle, marker_bundle, text_bundle, int_bundle, edge_bundle, pat_rep, colr_rep, view_rep,
        ws_tran, highl_filter, invis_filter, hlhsr_mode;
} Pdyns_ws_attrs;
typedef struct {
    Pdyn_mod content, post, unpost, del, ref;
} Pdyns_structs;
/* Function identifiers of this group. */
#define Pfn_set_disp_upd_st (6)
#define Pfn_set_line_rep (62)
#define Pfn_set_marker_rep (63)
#define Pfn_set_text_rep (64)
#define Pfn_set_int_rep (65)
#define Pfn_set_edge_rep (66)
#define Pfn_set_pat_rep (67)
#define Pfn_set_colr_rep (68)
#define Pfn_set_highl_filter (69)
#define Pfn_set_invis_filter (70)
#define Pfn_set_colr_model (71)
#define Pfn_set_hlhsr_mode (73)
#define Pfn_set_view_tran_in_pri (85)

/* Deferral and modification modes. Every change needs a regeneration here (the dynamics are
 * IRG): ASAP, BNIG and BNIL show it at once; ASTI and WAIT defer it under NIVE and UWOR (visual
 * state DEFER) and simulate it under UQUM (SIMULATED) until pupd_ws(PERFORM) or
 * predraw_all_structs. View representations, the workstation window and viewport and the HLHSR
 * mode have requested values and current ones (those of the picture), PUPD_PEND between. */
void pset_disp_upd_st(Pint ws_id, Pdefer_mode def_mode, Pmod_mode mod_mode);
void pinq_disp_upd_st(Pint ws_id, Pint* err_ind, Pdefer_mode* def_mode, Pmod_mode* mod_mode,
                      Pdisp_surf_empty* disp_empty, Pvisual_st* state);
void pinq_def_disp_upd_st(Pint ws_type, Pint* err_ind, Pdefer_mode* def_mode, Pmod_mode* mod_mode);
/* View 0 is the identity and cannot be set (115); errors 114, 101 for an index outside the table. */
void pinq_view_rep(Pint ws_id, Pint view_ind, Pint* err_ind, Pupd_st* upd_st, Pview_rep3* cur_rep,
                   Pview_rep3* req_rep);
void pinq_ws_tran3(Pint ws_id, Pint* err_ind, Pupd_st* upd_st, Plimit3* req_win_lim, Plimit3* cur_win_lim,
                   Plimit3* req_vp_lim, Plimit3* cur_vp_lim);
void pinq_ws_tran(Pint ws_id, Pint* err_ind, Pupd_st* upd_st, Plimit* req_win_lim, Plimit* cur_win_lim,
                  Plimit* req_vp_lim, Plimit* cur_vp_lim);
/* HLHSR modes: 0 none, 1 z-buffer (111 for others). */
void pset_hlhsr_mode(Pint ws_id, Pint hlhsr_mode);
void pinq_hlhsr_mode(Pint ws_id, Pint* err_ind, Pupd_st* upd_st, Pint* cur_mode, Pint* req_mode);
void pset_view_tran_in_pri(Pint ws_id, Pint view_ind, Pint ref_view_ind, Prel_pri priority);
/* Defined view indices in order of view transformation input priority, highest first. */
void pinq_list_view_inds(Pint ws_id, Pint length, Pint start, Pint* err_ind, Pint_list* view_inds,
                         Pint* total_length);
/* Filters: name sets as Pint_list; the inquiry's lists point into the store. */
void pset_highl_filter(Pint ws_id, const Pfilter* filter);
void pset_invis_filter(Pint ws_id, const Pfilter* filter);
void pinq_highl_filter(Pint ws_id, Pstore store, Pint* err_ind, Pfilter** filter);
void pinq_invis_filter(Pint ws_id, Pstore store, Pint* err_ind, Pfilter** filter);
void pinq_wss_posted(Pint struct_id, Pint length, Pint start, Pint* err_ind, Pint_list* ws_ids,
                     Pint* total_length);

/* Representations. Errors: 100 (bundle index < 1), 103 (a new entry beyond the table), 113
 * (colour index < 0), 104 linetype, 105 marker type, 106 font and precision, 107 edgetype, 108
 * interior style, 112 pattern index < 1, 116 pattern dimensions, 118 colour component. The
 * inquiries answer 101 for an undefined index with PINQ_SET and index 1's representation with
 * PINQ_REALIZED (widths and sizes within the facilities, text in STROKE precision, undefined
 * colour indices as 1). Interiors of style PSTYLE_PAT draw the pattern's cells. */
void pset_line_rep(Pint ws_id, Pint line_ind, const Pline_bundle* line_bundle);
void pset_marker_rep(Pint ws_id, Pint marker_ind, const Pmarker_bundle* marker_bundle);
void pset_text_rep(Pint ws_id, Pint text_ind, const Ptext_bundle* text_bundle);
void pset_int_rep(Pint ws_id, Pint int_ind, const Pint_bundle* int_bundle);
void pset_edge_rep(Pint ws_id, Pint edge_ind, const Pedge_bundle* edge_bundle);
void pset_pat_rep(Pint ws_id, Pint pat_ind, const Ppat_rep* pat_rep);
void pset_colr_rep(Pint ws_id, Pint colr_ind, const Pcolr_rep* colr_rep);
void pset_colr_model(Pint ws_id, Pint colr_model);
void pinq_line_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err_ind, Pline_bundle* rep);
void pinq_marker_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err_ind, Pmarker_bundle* rep);
void pinq_text_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err_ind, Ptext_bundle* rep);
void pinq_int_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err_ind, Pint_bundle* rep);
void pinq_edge_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err_ind, Pedge_bundle* rep);
void pinq_pat_rep(Pint ws_id, Pint index, Pinq_type type, Pstore store, Pint* err_ind, Ppat_rep** rep);
void pinq_colr_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err_ind, Pcolr_rep* rep);
void pinq_colr_model(Pint ws_id, Pint* err_ind, Pint* colr_model);
void pinq_list_line_inds(Pint ws_id, Pint length, Pint start, Pint* err_ind, Pint_list* inds,
                         Pint* total_length);
void pinq_list_marker_inds(Pint ws_id, Pint length, Pint start, Pint* err_ind, Pint_list* inds,
                           Pint* total_length);
void pinq_list_text_inds(Pint ws_id, Pint length, Pint start, Pint* err_ind, Pint_list* inds,
                         Pint* total_length);
void pinq_list_int_inds(Pint ws_id, Pint length, Pint start, Pint* err_ind, Pint_list* inds,
                        Pint* total_length);
void pinq_list_edge_inds(Pint ws_id, Pint length, Pint start, Pint* err_ind, Pint_list* inds,
                         Pint* total_length);
void pinq_list_pat_inds(Pint ws_id, Pint length, Pint start, Pint* err_ind, Pint_list* inds,
                        Pint* total_length);
void pinq_list_colr_inds(Pint ws_id, Pint length, Pint start, Pint* err_ind, Pint_list* inds,
                         Pint* total_length);

/* The workstation description tables (by workstation type; 52 for another number). Predefined
 * representations: errors 100 (or 112 for patterns, 113 for colours, 114 for views) below the
 * first index and 102 past the last. */
void pinq_ws_class(Pint ws_type, Pint* err_ind, Pws_class* ws_class);
void pinq_disp_space_size3(Pint ws_type, Pint* err_ind, Pdisp_space_size3* size);
void pinq_disp_space_size(Pint ws_type, Pint* err_ind, Pdisp_space_size* size);
void pinq_ws_st_table(Pint ws_type, Pint* err_ind, Pws_tables* lengths);
void pinq_num_disp_pris(Pint ws_type, Pint* err_ind, Pint* num_pris);
void pinq_dyns_ws_attrs(Pint ws_type, Pint* err_ind, Pdyns_ws_attrs* attrs);
void pinq_dyns_structs(Pint ws_type, Pint* err_ind, Pdyns_structs* dyns);
void pinq_line_facs(Pint ws_type, Pint length, Pint start, Pint* err_ind, Pline_facs* facs,
                    Pint* total_length);
void pinq_marker_facs(Pint ws_type, Pint length, Pint start, Pint* err_ind, Pmarker_facs* facs,
                      Pint* total_length);
void pinq_text_facs(Pint ws_type, Pint length, Pint start, Pint* err_ind, Ptext_facs* facs,
                    Pint* total_length);
void pinq_int_facs(Pint ws_type, Pint hatch_length, Pint hatch_start, Pint* err_ind, Pint_facs* facs,
                   Pint* total_hatch_length);
void pinq_edge_facs(Pint ws_type, Pint length, Pint start, Pint* err_ind, Pedge_facs* facs,
                    Pint* total_length);
void pinq_pat_facs(Pint ws_type, Pint* err_ind, Pint* num_pred_inds);
void pinq_colr_facs(Pint ws_type, Pint* err_ind, Pcolr_facs* facs);
void pinq_colr_model_facs(Pint ws_type, Pint length, Pint start, Pint* err_ind, Pint_list* models,
                          Pint* total_length, Pint* def_model);
void pinq_view_facs(Pint ws_type, Pint* err_ind, Pint* num_pred_views);
void pinq_hlhsr_id_facs(Pint ws_type, Pint length, Pint start, Pint* err_ind, Pint_list* ids,
                        Pint* total_length);
void pinq_hlhsr_mode_facs(Pint ws_type, Pint length, Pint start, Pint* err_ind, Pint_list* modes,
                          Pint* total_length);
void pinq_anno_facs(Pint ws_type, Pint length, Pint start, Pint* err_ind, Pint_list* styles,
                    Pint* total_length, Pint* num_char_hts, Pfloat* min_char_ht, Pfloat* max_char_ht);
/* The PHIGS description table's modelling clipping: distinct planes and operators. */
void pinq_model_clip_facs(Pint length, Pint start, Pint* err_ind, Pint* num_planes, Pint_list* ops,
                          Pint* total_length);
void pinq_pred_line_rep(Pint ws_type, Pint index, Pint* err_ind, Pline_bundle* rep);
void pinq_pred_marker_rep(Pint ws_type, Pint index, Pint* err_ind, Pmarker_bundle* rep);
void pinq_pred_text_rep(Pint ws_type, Pint index, Pint* err_ind, Ptext_bundle* rep);
void pinq_pred_int_rep(Pint ws_type, Pint index, Pint* err_ind, Pint_bundle* rep);
void pinq_pred_edge_rep(Pint ws_type, Pint index, Pint* err_ind, Pedge_bundle* rep);
void pinq_pred_pat_rep(Pint ws_type, Pint index, Pstore store, Pint* err_ind, Ppat_rep** rep);
void pinq_pred_colr_rep(Pint ws_type, Pint index, Pint* err_ind, Pcolr_rep* rep);
void pinq_pred_view_rep(Pint ws_type, Pint index, Pint* err_ind, Pview_rep3* rep);

/* ==== input: logical input devices (INITIALIZE, modes, REQUEST, SAMPLE, events, inquiries) ====
 * Every OUTIN type (PWST_OFFSCREEN, PWST_WINDOW) has 1 locator, 1 stroke, 12 valuators,
 * 4 choices, 1 pick and 1 string device (pinq_num_avail_in). Errors: 3 and 54 (workstation),
 * 61 (not of category INPUT or OUTIN; 60 for pick: not OUTIN), 250 (no such device), 251 (not in
 * REQUEST mode), 252 (not in SAMPLE mode), 253 (warning: prompt/echo type not available, type 1
 * with the default data record used instead), 254 (echo area/volume with min >= max),
 * 255 (echo area/volume outside the display space), 260 (data record), 261 (initial value),
 * 262/263 (initial stroke/string longer than the buffer), 114 (view index not in the view
 * table), 259 (GET of another class than the current event's), 256 (warning: queue overflow).
 * A refused call changes nothing.
 *
 * Operator actions come from an input script attached by ESCAPE PUESC_INPUT_SCRIPT (the
 * in-record's escape_in_u11: ws_id, and the script's text, or NULL and a file name). One action
 * a line, positions in device coordinates of the display space measured from its top left
 * (y down, pixels of the PWST_OFFSCREEN image):
 *     pick X Y          locator X Y        stroke X1 Y1 X2 Y2 ...    move X Y
 *     valuator D V      choice N|NAME      string TEXT               break      wait
 * ("device D" after pick, locator, stroke, choice or move addresses device D; # starts a
 * comment, except on a string line, whose text runs to the end of the line).
 * A REQUEST takes lines until one satisfies it ("break": status NONE); each SAMPLE first
 * delivers the script's next line, if any; AWAIT EVENT takes lines until an event is queued
 * ("wait" ends it with class NONE, as does the end of the script). A REQUEST with no script
 * attached is error 250, one whose script has ended PE_INPUT_SCRIPT_ENDED, and an action that
 * does not fit its device (a value outside the valuator's range) 351. Errors of the escape: 54,
 * 61, 351 (no script given, or it cannot be read or parsed). */
#define PUESC_INPUT_SCRIPT (-11)
#define PE_INPUT_SCRIPT_ENDED (-206) /* error: the script ended while a REQUEST waits */

typedef enum { POP_REQ, POP_SAMPLE, POP_EVENT } Pop_mode;
typedef enum { PSWITCH_NO_ECHO, PSWITCH_ECHO } Pecho_switch;
typedef enum { PIN_STATUS_NONE, PIN_STATUS_OK, PIN_STATUS_NO_IN } Pin_status;
typedef enum { PIN_NONE, PIN_LOC, PIN_STROKE, PIN_VAL, PIN_CHOICE, PIN_PICK, PIN_STRING } Pin_class;
typedef enum { PSIMULT_NO_MORE, PSIMULT_MORE } Pmore_simult_events;
typedef enum { PPR_OFF, PPR_ON } Ppr_switch;
/* Pinq_type and Pfilter: see the workstation state section above. */
typedef struct {
    Pint struct_id;
    Pint pick_id;
    Pint elem_pos;
} Ppick_path_elem;
typedef struct {
    Pint depth;
    Ppick_path_elem* path_list;
} Ppick_path;
typedef struct {
    Pint loc, stroke, val, choice, pick, string;
} Pnum_in;

/* The standard's prompt/echo type numbers (the data record's member pet_rN belongs to type N);
 * which of them a device offers, its workstation description says (pinq_def_loc_data3, ...). */
#define PLOC_DEF 1
#define PLOC_CROSS_HAIR 2
#define PLOC_TRACK_CROSS 3
#define PLOC_RUB_BAND 4
#define PLOC_RECT 5
#define PLOC_DIGIT 6
#define PSTROKE_DEF 1
#define PSTROKE_DIGIT 2
#define PSTROKE_MARKER 3
#define PSTROKE_LINE 4
#define PVAL_DEF 1
#define PVAL_GRAPH 2
#define PVAL_DIGIT 3
#define PCHOICE_DEF 1
#define PCHOICE_PR_ECHO 2
#define PCHOICE_STRING_PR 3
#define PCHOICE_STRING_IN 4
#define PCHOICE_STRUCT 5
#define PPICK_DEF 1
#define PPICK_GROUP_HIGHL 2
#define PPICK_STRUCT_NETWORK 3
#define PSTRING_DEF 1

/* Data records. Stroke and string: buffer_size in [1, 4096] (points, characters), init_pos in
 * [1, initial length + 1], intervals >= 0. Valuator: finite low < high. Choice: type 2 gives one
 * prompt switch and type 3 one string per alternative (1 to 64 alternatives; a script may
 * choose a type 3 alternative by its string). */
typedef struct {
    union {
        struct {
            Pint unused;
        } pet_r1, pet_r2, pet_r3;
    } pets;
} Ploc_data;
typedef Ploc_data Ploc_data3;
typedef struct {
    Pint buffer_size;
    Pint init_pos;
    Pfloat x_interval, y_interval, time_interval;
    union {
        struct {
            Pint unused;
        } pet_r1, pet_r2;
    } pets;
} Pstroke_data;
typedef struct {
    Pint buffer_size;
    Pint init_pos;
    Pfloat x_interval, y_interval, z_interval, time_interval;
    union {
        struct {
            Pint unused;
        } pet_r1, pet_r2;
    } pets;
} Pstroke_data3;
typedef struct {
    Pfloat low, high;
    union {
        struct {
            Pint unused;
        } pet_r1, pet_r2;
    } pets;
} Pval_data;
typedef Pval_data Pval_data3;
typedef struct {
    union {
        struct {
            Pint unused;
        } pet_r1;
        struct {
            Pint num_prompts;
            Ppr_switch* prompts;
        } pet_r2;
        struct {
            Pint num_strings;
            char** strings;
        } pet_r3;
    } pets;
} Pchoice_data;
typedef Pchoice_data Pchoice_data3;
typedef struct {
    union {
        struct {
            Pint unused;
        } pet_r1, pet_r2;
    } pets;
} Ppick_data;
typedef Ppick_data Ppick_data3;
typedef struct {
    Pint buffer_size;
    Pint init_pos;
    union {
        struct {
            Pint unused;
        } pet_r1;
    } pets;
} Pstring_data;
typedef Pstring_data Pstring_data3;

/* ISO function identifiers of the input functions. */
#define Pfn_set_pick_filter (130)
#define Pfn_init_loc3 (131)
#define Pfn_init_loc (132)
#define Pfn_init_stroke3 (133)
#define Pfn_init_stroke (134)
#define Pfn_init_val3 (135)
#define Pfn_init_val (136)
#define Pfn_init_choice3 (137)
#define Pfn_init_choice (138)
#define Pfn_init_pick3 (139)
#define Pfn_init_pick (140)
#define Pfn_init_string3 (141)
#define Pfn_init_string (142)
#define Pfn_set_loc_mode (143)
#define Pfn_set_stroke_mode (144)
#define Pfn_set_val_mode (145)
#define Pfn_set_choice_mode (146)
#define Pfn_set_pick_mode (147)
#define Pfn_set_string_mode (148)
#define Pfn_req_loc3 (149)
#define Pfn_req_loc (150)
#define Pfn_req_stroke3 (151)
#define Pfn_req_stroke (152)
#define Pfn_req_val (153)
#define Pfn_req_choice (154)
#define Pfn_req_pick (155)
#define Pfn_req_string (156)
#define Pfn_sample_loc3 (157)
#define Pfn_sample_loc (158)
#define Pfn_sample_stroke3 (159)
#define Pfn_sample_stroke (160)
#define Pfn_sample_val (161)
#define Pfn_sample_choice (162)
#define Pfn_sample_pick (163)
#define Pfn_sample_string (164)
#define Pfn_await_event (165)
#define Pfn_flush_events (166)
#define Pfn_get_loc3 (167)
#define Pfn_get_loc (168)
#define Pfn_get_stroke3 (169)
#define Pfn_get_stroke (170)
#define Pfn_get_val (171)
#define Pfn_get_choice (172)
#define Pfn_get_pick (173)
#define Pfn_get_string (174)

/* INITIALIZE: the device must be in REQUEST mode. Echo areas and volumes are in device
 * coordinates of the display space (y up, z in [0, 1]); the 2D forms keep z in [0, 1]. */
void pinit_loc3(Pint ws_id, Pint loc_num, Pint init_view_ind, const Ppoint3* init_loc_pos, Pint pet,
                const Plimit3* echo_vol, const Ploc_data3* loc_data);
void pinit_loc(Pint ws_id, Pint loc_num, Pint init_view_ind, const Ppoint* init_loc_pos, Pint pet,
               const Plimit* echo_area, const Ploc_data* loc_data);
void pinit_stroke3(Pint ws_id, Pint stroke_num, Pint init_view_ind, const Ppoint_list3* init_stroke, Pint pet,
                   const Plimit3* echo_vol, const Pstroke_data3* stroke_data);
void pinit_stroke(Pint ws_id, Pint stroke_num, Pint init_view_ind, const Ppoint_list* init_stroke, Pint pet,
                  const Plimit* echo_area, const Pstroke_data* stroke_data);
void pinit_val3(Pint ws_id, Pint val_num, Pfloat init_value, Pint pet, const Plimit3* echo_vol,
                const Pval_data3* val_data);
void pinit_val(Pint ws_id, Pint val_num, Pfloat init_value, Pint pet, const Plimit* echo_area,
               const Pval_data* val_data);
void pinit_choice3(Pint ws_id, Pint choice_num, Pin_status init_status, Pint init_choice, Pint pet,
                   const Plimit3* echo_vol, const Pchoice_data3* choice_data);
void pinit_choice(Pint ws_id, Pint choice_num, Pin_status init_status, Pint init_choice, Pint pet,
                  const Plimit* echo_area, const Pchoice_data* choice_data);
void pinit_pick3(Pint ws_id, Pint pick_num, Pin_status init_status, const Ppick_path* init_pick, Pint pet,
                 const Plimit3* echo_vol, const Ppick_data3* pick_data, Ppath_order order);
void pinit_pick(Pint ws_id, Pint pick_num, Pin_status init_status, const Ppick_path* init_pick, Pint pet,
                const Plimit* echo_area, const Ppick_data* pick_data, Ppath_order order);
void pinit_string3(Pint ws_id, Pint string_num, const char* init_string, Pint pet, const Plimit3* echo_vol,
                   const Pstring_data3* string_data);
void pinit_string(Pint ws_id, Pint string_num, const char* init_string, Pint pet, const Plimit* echo_area,
                  const Pstring_data* string_data);

/* SET <class> MODE: a device entering SAMPLE or EVENT mode starts from its initial measure. */
void pset_loc_mode(Pint ws_id, Pint loc_num, Pop_mode op_mode, Pecho_switch echo_switch);
void pset_stroke_mode(Pint ws_id, Pint stroke_num, Pop_mode op_mode, Pecho_switch echo_switch);
void pset_val_mode(Pint ws_id, Pint val_num, Pop_mode op_mode, Pecho_switch echo_switch);
void pset_choice_mode(Pint ws_id, Pint choice_num, Pop_mode op_mode, Pecho_switch echo_switch);
void pset_pick_mode(Pint ws_id, Pint pick_num, Pop_mode op_mode, Pecho_switch echo_switch);
void pset_string_mode(Pint ws_id, Pint string_num, Pop_mode op_mode, Pecho_switch echo_switch);
/* SET PICK FILTER: a primitive is pickable when its name set meets the inclusion set and misses
 * the exclusion set (both start empty: nothing is pickable until this is called). */
void pset_pick_filter(Pint ws_id, Pint pick_num, const Pfilter* filter);

/* REQUEST: stroke->points must hold the device's buffer size, string the buffer size + 1 chars;
 * pick->path_list gets the pick path's first `depth` items and pick->depth the path's real
 * depth, which can be more (as the sample implementation). A pick that hits nothing
 * is PIN_STATUS_NO_IN, a break PIN_STATUS_NONE. */
void preq_loc3(Pint ws_id, Pint loc_num, Pin_status* in_status, Pint* view_ind, Ppoint3* loc_pos);
void preq_loc(Pint ws_id, Pint loc_num, Pin_status* in_status, Pint* view_ind, Ppoint* loc_pos);
void preq_stroke3(Pint ws_id, Pint stroke_num, Pin_status* in_status, Pint* view_ind, Ppoint_list3* stroke);
void preq_stroke(Pint ws_id, Pint stroke_num, Pin_status* in_status, Pint* view_ind, Ppoint_list* stroke);
void preq_val(Pint ws_id, Pint val_num, Pin_status* in_status, Pfloat* val);
void preq_choice(Pint ws_id, Pint choice_num, Pin_status* in_status, Pint* choice);
void preq_pick(Pint ws_id, Pint pick_num, Pint depth, Pin_status* in_status, Ppick_path* pick);
void preq_string(Pint ws_id, Pint string_num, Pin_status* in_status, char* string);

void psample_loc3(Pint ws_id, Pint loc_num, Pint* view_ind, Ppoint3* loc_pos);
void psample_loc(Pint ws_id, Pint loc_num, Pint* view_ind, Ppoint* loc_pos);
void psample_stroke3(Pint ws_id, Pint stroke_num, Pint* view_ind, Ppoint_list3* stroke);
void psample_stroke(Pint ws_id, Pint stroke_num, Pint* view_ind, Ppoint_list* stroke);
void psample_val(Pint ws_id, Pint val_num, Pfloat* val);
void psample_choice(Pint ws_id, Pint choice_num, Pin_status* choice_in_status, Pint* choice);
void psample_pick(Pint ws_id, Pint pick_num, Pint depth, Pin_status* pick_in_status, Ppick_path* pick);
void psample_string(Pint ws_id, Pint string_num, char* string);

/* AWAIT EVENT (timeout in seconds) moves the oldest event to the current event report, which
 * GET <class> reads (259 when it is of another class); FLUSH DEVICE EVENTS drops one device's. */
void pawait_event(Pfloat timeout, Pint* ws_id, Pin_class* dev_class, Pint* in_num);
void pflush_events(Pint ws_id, Pin_class dev_class, Pint dev_num);
void pget_loc3(Pint* view_ind, Ppoint3* loc_pos);
void pget_loc(Pint* view_ind, Ppoint* loc_pos);
void pget_stroke3(Pint* view_ind, Ppoint_list3* stroke);
void pget_stroke(Pint* view_ind, Ppoint_list* stroke);
void pget_val(Pfloat* val);
void pget_choice(Pin_status* in_status, Pint* choice);
void pget_pick(Pint depth, Pin_status* in_status, Ppick_path* pick);
void pget_string(char* string);

/* Device states: what INITIALIZE and SET MODE set (SET and REALIZED answer alike); variable
 * parts (strokes, paths, filters, strings, data records) live in the store. */
void pinq_loc_st3(Pint ws_id, Pint loc_num, Pinq_type type, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                  Pecho_switch* echo_switch, Pint* init_view_ind, Ppoint3* init_loc_pos, Pint* prompt_echo,
                  Plimit3* echo_vol, Ploc_data3** loc_data);
void pinq_loc_st(Pint ws_id, Pint loc_num, Pinq_type type, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                 Pecho_switch* echo_switch, Pint* init_view_ind, Ppoint* init_loc_pos, Pint* prompt_echo,
                 Plimit* echo_area, Ploc_data** loc_data);
void pinq_stroke_st3(Pint ws_id, Pint stroke_num, Pinq_type type, Pstore store, Pint* err_ind,
                     Pop_mode* op_mode, Pecho_switch* echo_switch, Pint* init_view_ind,
                     Ppoint_list3** init_stroke, Pint* prompt_echo, Plimit3* echo_vol,
                     Pstroke_data3** stroke_data);
void pinq_stroke_st(Pint ws_id, Pint stroke_num, Pinq_type type, Pstore store, Pint* err_ind,
                    Pop_mode* op_mode, Pecho_switch* echo_switch, Pint* init_view_ind,
                    Ppoint_list** init_stroke, Pint* prompt_echo, Plimit* echo_area,
                    Pstroke_data** stroke_data);
void pinq_val_st3(Pint ws_id, Pint val_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                  Pecho_switch* echo_switch, Pfloat* init_value, Pint* prompt_echo, Plimit3* echo_vol,
                  Pval_data3** val_data);
void pinq_val_st(Pint ws_id, Pint val_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                 Pecho_switch* echo_switch, Pfloat* init_value, Pint* prompt_echo, Plimit* echo_area,
                 Pval_data** val_data);
void pinq_choice_st3(Pint ws_id, Pint choice_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                     Pecho_switch* echo_switch, Pin_status* init_status, Pint* init_choice, Pint* prompt_echo,
                     Plimit3* echo_vol, Pchoice_data3** choice_data);
void pinq_choice_st(Pint ws_id, Pint choice_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                    Pecho_switch* echo_switch, Pin_status* init_status, Pint* init_choice, Pint* prompt_echo,
                    Plimit* echo_area, Pchoice_data** choice_data);
void pinq_pick_st3(Pint ws_id, Pint pick_num, Pinq_type type, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                   Pecho_switch* echo_switch, Pfilter** pick_filter, Pin_status* init_status,
                   Ppick_path** init_pick, Pint* prompt_echo, Plimit3* echo_vol, Ppick_data3** pick_data,
                   Ppath_order* order);
void pinq_pick_st(Pint ws_id, Pint pick_num, Pinq_type type, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                  Pecho_switch* echo_switch, Pfilter** pick_filter, Pin_status* init_status,
                  Ppick_path** init_pick, Pint* prompt_echo, Plimit* echo_area, Ppick_data** pick_data,
                  Ppath_order* order);
void pinq_string_st3(Pint ws_id, Pint string_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                     Pecho_switch* echo_switch, char** init_string, Pint* prompt_echo, Plimit3* echo_vol,
                     Pstring_data3** string_data);
void pinq_string_st(Pint ws_id, Pint string_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                    Pecho_switch* echo_switch, char** init_string, Pint* prompt_echo, Plimit* echo_area,
                    Pstring_data** string_data);

/* Default device data of a workstation type (52: no such type, 61: not INPUT or OUTIN, 250):
 * the prompt/echo types, the whole display space as echo volume, the default data record. */
void pinq_def_loc_data3(Pint ws_type, Pint loc_num, Pstore store, Pint* err_ind, Ppoint3* loc_pos,
                        Pint_list** pet_list, Plimit3* echo_vol, Ploc_data3** loc_data);
void pinq_def_loc_data(Pint ws_type, Pint loc_num, Pstore store, Pint* err_ind, Ppoint* loc_pos,
                       Pint_list** pet_list, Plimit* echo_area, Ploc_data** loc_data);
void pinq_def_stroke_data3(Pint ws_type, Pint stroke_num, Pstore store, Pint* err_ind, Pint* max_buf_size,
                           Pint_list** pet_list, Plimit3* echo_vol, Pstroke_data3** stroke_data);
void pinq_def_stroke_data(Pint ws_type, Pint stroke_num, Pstore store, Pint* err_ind, Pint* max_buf_size,
                          Pint_list** pet_list, Plimit* echo_area, Pstroke_data** stroke_data);
void pinq_def_val_data3(Pint ws_type, Pint val_num, Pstore store, Pint* err_ind, Pfloat* def_value,
                        Pint_list** pet_list, Plimit3* echo_vol, Pval_data3** val_data);
void pinq_def_val_data(Pint ws_type, Pint val_num, Pstore store, Pint* err_ind, Pfloat* def_value,
                       Pint_list** pet_list, Plimit* echo_area, Pval_data** val_data);
void pinq_def_choice_data3(Pint ws_type, Pint choice_num, Pstore store, Pint* err_ind, Pint* max_choices,
                           Pint_list** pet_list, Plimit3* echo_vol, Pchoice_data3** choice_data);
void pinq_def_choice_data(Pint ws_type, Pint choice_num, Pstore store, Pint* err_ind, Pint* max_choices,
                          Pint_list** pet_list, Plimit* echo_area, Pchoice_data** choice_data);
void pinq_def_pick_data3(Pint ws_type, Pint pick_num, Pstore store, Pint* err_ind, Pint_list** pet_list,
                         Plimit3* echo_vol, Ppick_data3** pick_data);
void pinq_def_pick_data(Pint ws_type, Pint pick_num, Pstore store, Pint* err_ind, Pint_list** pet_list,
                        Plimit* echo_area, Ppick_data** pick_data);
void pinq_def_string_data3(Pint ws_type, Pint string_num, Pstore store, Pint* err_ind, Pint* max_buf_size,
                           Pint_list** pet_list, Plimit3* echo_vol, Pstring_data3** string_data);
void pinq_def_string_data(Pint ws_type, Pint string_num, Pstore store, Pint* err_ind, Pint* max_buf_size,
                          Pint_list** pet_list, Plimit* echo_area, Pstring_data** string_data);
void pinq_num_avail_in(Pint ws_type, Pint* err_ind, Pnum_in* num_in);
/* INQUIRE INPUT QUEUE OVERFLOW (3: no workstation open, 257: no overflow since the last ask)
 * and INQUIRE MORE SIMULTANEOUS EVENTS (of the current event report). */
void pinq_in_overf(Pint* err_ind, Pint* ws_id, Pin_class* in_class, Pint* in_num);
void pinq_more_simult_events(Pint* err_ind, Pmore_simult_events* simult_events);

/* ==== incremental spatial search, metafiles, text extent and PHIGS PLUS ====
 * (the names of this group are listed in COVERAGE.md; see README.md for the semantics) */

/* Lists of name set filters (Pfilter and Pinq_type: see the workstation state section). */
typedef struct {
    Pint num_filters;
    Pfilter* filters;
} Pfilter_list;

/* Function identifiers of this group: metafiles (ISO 9593-4) and PHIGS PLUS (ISO 9592-4). */
#define Pfn_write_item (175)
#define Pfn_get_item_type (176)
#define Pfn_read_item (177)
#define Pfn_interpret_item (178)
#define Pfn_nuni_bsp_curv (307)
#define Pfn_nuni_bsp_surf (308)
#define Pfn_fill_area_set3_data (302)
#define Pfn_tri_strip3_data (305)
#define Pfn_quad_mesh3_data (306)
#define Pfn_set_line_shad_meth (311)
#define Pfn_set_face_disting_mode (314)
#define Pfn_set_face_cull_mode (315)
#define Pfn_set_int_shad_meth (317)
#define Pfn_set_refl_props (318)
#define Pfn_set_refl_eqn (319)
#define Pfn_set_back_int_style (320)
#define Pfn_set_back_int_style_ind (321)
#define Pfn_set_back_int_colr (322)
#define Pfn_set_back_int_shad_meth (323)
#define Pfn_set_back_refl_props (324)
#define Pfn_set_back_refl_eqn (325)
#define Pfn_set_light_src_state (326)
#define Pfn_set_curve_approx (328)
#define Pfn_set_surf_approx (329)
#define Pfn_set_para_surf_characs (330)
#define Pfn_set_dcue_ind (332)
#define Pfn_set_colr_map_ind (333)
#define Pfn_set_light_src_rep (340)
#define Pfn_set_dcue_rep (341)

/* INCREMENTAL SPATIAL SEARCH (3): the next output primitive after the start path's element
 * whose locus lies within `dist` of the search reference point (world coordinates; dist <= 0:
 * the locus must contain the point) and whose name set every normal filter accepts and every
 * inverted filter rejects, searching to the end of the structure at position `ceiling` (1-based)
 * of the start path. The 2D form takes z = 0. Model clipping cuts the loci when mclip_flag is
 * PIND_CLIP. The found path (empty when nothing qualifies) is a simple list. Errors (in
 * *err_ind): 203 start path not in the CSS, 204 ceiling outside 1 .. path length. */
void pincr_spa_search3(const Ppoint3* ref, Pfloat dist, const Pelem_ref_list* start_path,
                       Pclip_ind mclip_flag, Pint ceiling, const Pfilter_list* norm_filter,
                       const Pfilter_list* inv_filter, Pint num_elems_appl_list, Pint start_ind,
                       Pint* err_ind, Pelem_ref_list* found_path, Pint* num_elems_impl_list);
void pincr_spa_search(const Ppoint* ref, Pfloat dist, const Pelem_ref_list* start_path, Pclip_ind mclip_flag,
                      Pint ceiling, const Pfilter_list* norm_filter, const Pfilter_list* inv_filter,
                      Pint num_elems_appl_list, Pint start_ind, Pint* err_ind, Pelem_ref_list* found_path,
                      Pint* num_elems_impl_list);

/* Metafiles. This implementation has no metafile workstation type: pwrite_item answers error 56
 * (not of category MO), pget_item_type and pread_item 58 (not of category MI) on any open
 * workstation (3, 54 first); pinterpret_item knows no item type (304; 301 for a negative
 * length). */
typedef union {
    struct {
        Pint unused;
    } item_u1;
    Pdata unsupp;
} Pitem_data;
void pwrite_item(Pint ws_id, Pint item_type, Pint item_data_length, const Pitem_data* item_data);
void pget_item_type(Pint ws_id, Pint* item_type, Pint* item_data_length);
void pread_item(Pint ws_id, Pint max_item_data_length, Pitem_data* item_data);
void pinterpret_item(Pint type, Pint item_data_length, const Pitem_data* item_data);

/* INQUIRE TEXT EXTENT: the rectangle of the character bodies and the concatenation point in
 * text local coordinates (units of char_ht, alignment applied) of the Hershey stroke fonts the
 * workstations draw: fonts 1 (Roman simplex), 2 (duplex), 3 (triplex), 4 (script); 106 for any
 * other font, 52 for an unknown workstation type. */
void pinq_text_extent(Pint ws_type, Pint font, Pfloat char_expan, Pfloat char_space, Pfloat char_ht,
                      Ptext_path text_path, Phor_text_align hor_align, Pvert_text_align vert_align,
                      const char* str, Pint* err_ind, Prect* rect, Ppoint* offset);

/* ---- PHIGS PLUS attributes */
#define PSD_NONE 1
#define PSD_COLOUR 2
#define PSD_DOT_PRODUCT 3
#define PSD_NORMAL 4
#define PREFL_NONE 1
#define PREFL_AMBIENT 2
#define PREFL_AMB_DIFF 3
#define PREFL_AMB_DIFF_SPEC 4
void pset_line_shad_meth(Pint shad_meth);
void pset_int_shad_meth(Pint shad_meth);
void pset_back_int_shad_meth(Pint shad_meth);
void pset_refl_eqn(Pint refl_eqn);
void pset_back_refl_eqn(Pint refl_eqn);
void pset_refl_props(const Prefl_props* refl_props);
void pset_back_refl_props(const Prefl_props* refl_props);
void pset_back_int_style(Pint_style style);
void pset_back_int_style_ind(Pint style_ind);
void pset_back_int_colr(const Pgcolr* colr);
void pset_face_disting_mode(Pdisting_mode mode);
void pset_face_cull_mode(Pcull_mode mode);
/* SET LIGHT SOURCE STATE: the indices to activate and to deactivate (one list each). */
void pset_light_src_state(const Pint_list* activation, const Pint_list* deactivation);
void pset_dcue_ind(Pint dcue_ind);
void pset_colr_map_ind(Pint colr_map_ind);
void pset_curve_approx(Pint type, Pfloat value);
void pset_surf_approx(Pint type, Pfloat u_val, Pfloat v_val);
void pset_para_surf_characs(Pint psc_type, const Ppara_surf_characs* data);

/* ---- PHIGS PLUS NURBS primitives. A rational control point is homogeneous (w x, w y, w z, w),
 * w > 0. Knots: order + number of control points, non-decreasing. A surface's grid holds
 * num_points.size_x (u) x num_points.size_y (v) points, u running fastest. Trimming curves are
 * closed loops in (u, v) (rational: (w u, w v, w)); a curve trims over [tmin, tmax], within its
 * knots' domain (tmin == tmax: the whole domain), and is kept as that part (answered with its own
 * knots, points and range). A visible (PEDGE_ON) trimming curve is drawn along the surface in
 * the edge colour and width while the edge flag is on; its approximation (PCURV_*, chordal values
 * in (u, v)) says how finely it is followed, for trimming and for drawing. Bad data is refused
 * with -202 naming the rule. */
/* NON-UNIFORM B-SPLINE CURVE drawn over [min, max] (min == max: the whole domain). */
void pnuni_bsp_curv(Pint order, const Pfloat_list* knots, Prational rationality, const Ppoint_list34* cpts,
                    Pfloat min, Pfloat max);
void pnuni_bsp_surf(Pint uorder, Pint vorder, const Pfloat_list* uknots, const Pfloat_list* vknots,
                    Prational rationality, const Ppoint_grid34* grid, Pint num_trim_loops,
                    const Ptrimcurve_list* trim_loops);

/* ---- PHIGS PLUS primitives with data. FILL AREA SET 3 WITH DATA keeps a facet colour and
 * normal, per-vertex colours and normals and, with PEDGE_VISIBILITY, a flag per contour edge
 * (edata[c].edgedata[k]: the edge from vertex k to k + 1, the last back to the first; with the
 * edge flag on only the edges flagged PEDGE_ON are drawn). Triangle strips and quadrilateral
 * meshes keep per-vertex data and facet data: one per triangle (nv - 2; triangle k has vertices
 * k, k + 1, k + 2) or per quadrilateral ((size_x - 1) x (size_y - 1), x fastest). Vertex colours
 * take precedence over facet colours, which colour their facet flat; vertex normals over facet
 * normals, which also give their facet's front. A quadrilateral mesh of dim.size_x x dim.size_y
 * points runs x fastest. */
void pfill_area_set3_data(Pint fflag, Pint eflag, Pint vflag, Pint colr_type, const Pfacet_data3* fdata,
                          Pint nfa, const Pedge_data_list* edata, const Pfacet_vdata_list3* vdata);
void ptri_strip3_data(Pint fflag, Pint vflag, Pint colr_type, Pint nv, const Pfacet_data_arr3* fdata,
                      const Pfacet_vdata_arr3* vdata);
void pquad_mesh3_data(Pint fflag, Pint vflag, Pint colr_type, const Pint_size* dim,
                      const Pfacet_data_arr3* fdata, const Pfacet_vdata_arr3* vdata);
/* COMPUTE FILL AREA SET GEOMETRIC NORMAL: the unit normal (P2 - P1) x (P3 - P1) of the first three
 * vertices that are not collinear (-202 when there are none). An inquiry-style utility. */
void pcomp_fill_area_set_gnorm(Pint vflag, Pint nfa, const Pfacet_vdata_list3* vdata, Pint* err_ind,
                               Pvec3* norm);

/* ---- PHIGS PLUS representations: light sources and depth cueing. Colours are direct (any colour
 * model, held as its RGB) or an index resolved through the workstation's colour table when set
 * (113 for a negative index). */
#define PLIGHT_AMBIENT 1
#define PLIGHT_DIRECTIONAL 2
#define PLIGHT_POSITIONAL 3
#define PLIGHT_SPOT 4
typedef struct {
    Pgcolr colr;
} Pamb_light_src_rec;
typedef struct {
    Pgcolr colr;
    Pvec3 dir;
} Pdir_light_src_rec;
typedef struct {
    Pgcolr colr;
    Ppoint3 pos;
    Pfloat coef[2]; /* attenuation: constant, linear */
} Ppos_light_src_rec;
typedef struct {
    Pgcolr colr;
    Ppoint3 pos;
    Pvec3 dir;
    Pfloat exp;
    Pfloat coef[2];
    Pfloat angle; /* spread angle, radians, in [0, pi] */
} Pspot_light_src_rec;
typedef union {
    Pamb_light_src_rec ambient;
    Pdir_light_src_rec directional;
    Ppos_light_src_rec positional;
    Pspot_light_src_rec spot;
    Pdata unsupp;
} Plight_src_rec;
typedef struct {
    Pint type;
    Plight_src_rec rec;
} Plight_src_bundle;
typedef enum { PSUPPRESSED, PALLOWED } Pdcue_mode;
typedef struct {
    Pdcue_mode mode;
    Pfloat ref_planes[2]; /* front, back (NPC z) */
    Pfloat scaling[2];    /* front, back */
    Pgcolr colr;
} Pdcue_bundle;
/* Light sources: index >= 1 (100), table full 103, type outside 1..4 (2202). Depth cue: index
 * >= 1 (100; index 0 is the predefined suppressed entry), table full 103. A NaN or infinite
 * direct colour component is 136, any other NaN or infinite real -208. PINQ_SET answers the
 * values set (colours as given: PINDIRECT with the index, drawn through the colour table as it is
 * when drawn, or direct in their model; a colour type outside PINDIRECT .. PMODEL_HLS is 2202, an
 * index below 0 is 113); PINQ_REALIZED what is drawn: colours as PMODEL_RGB clamped to [0, 1],
 * light directions of unit length ((0, 0, -1) for a zero one), attenuation coefficients >= 0, spot
 * exponent in [0, 128] and spread angle in [0, pi]; depth cue planes and scales clamped to [0, 1]
 * and the planes ordered front >= back (a reversed pair swapped with its scales). 101 for an
 * index not defined. */
void pset_light_src_rep(Pint ws_id, Pint light_src_ind, const Plight_src_bundle* light_src_rep);
void pinq_light_src_rep(Pint ws_id, Pint light_src_ind, Pinq_type type, Pint* err_ind,
                        Plight_src_bundle* light_src_rep);
void pinq_list_light_src_inds(Pint ws_id, Pint num_elems_appl_list, Pint start_ind, Pint* err_ind,
                              Pint_list* light_src_inds, Pint* num_elems_impl_list);
/* Predefined representations (every type: light 1 white ambient, depth cue 0 suppressed; 102 for
 * any other index) and the light source facilities (the four types; max: how many may be
 * active at once, the light table's size; the number of predefined entries). */
typedef struct {
    Pint_list types;
    Pint max;
    Pint num_pred_inds;
} Plight_src_facs;
void pinq_pred_light_src_rep(Pint ws_type, Pint light_src_ind, Pint* err_ind,
                             Plight_src_bundle* light_src_rep);
void pinq_pred_dcue_rep(Pint ws_type, Pint dcue_ind, Pint* err_ind, Pdcue_bundle* dcue_rep);
void pinq_light_src_facs(Pint ws_type, Pint num_elems_appl_list, Pint start_ind, Pint* err_ind,
                         Plight_src_facs* facs, Pint* num_elems_impl_list);
/* More facilities of every type: the predefined depth cue entries (1), the rendering colour
 * models (PRCM_RGB .. PRCM_HLS, each drawn), and the curve and surface facilities: the approximation criteria
 * drawn (workstation dependent, constant subdivision between knots, chordal deviation), trimming curves
 * workstation dependent, surface characteristics PSC_NONE .. PSC_LEVEL_CURVES_WC, and no
 * limit on B-spline orders (INT_MAX). */
typedef struct {
    Pint max_bsp_order;
    Pint max_tc_order;
    Pint_list cat_types;
    Pint_list sat_types;
    Pint_list tcat_types;
    Pint_list psc_types;
} Pcurvsurf_facs;
void pinq_dcue_facs(Pint ws_type, Pint* err_ind, Pint* num_pred_inds);
/* The direct colour models (PMODEL_RGB .. PMODEL_HLS); the total comes before the list, as in the PHIGS PLUS
 * binding. */
void pinq_direct_colr_model_facs(Pint ws_type, Pint num_elems_appl_list, Pint start_ind, Pint* err_ind,
                                 Pint* num_elems_impl_list, Pint_list* models);
void pinq_rendering_colr_model_facs(Pint ws_type, Pint num_elems_appl_list, Pint start_ind, Pint* err_ind,
                                    Pint_list* models, Pint* num_elems_impl_list);
void pinq_curv_surf_facs(Pint ws_type, Pint cat_len, Pint cat_st, Pint sat_len, Pint sat_st, Pint tcat_len,
                         Pint tcat_st, Pint psc_len, Pint psc_st, Pint* err_ind, Pcurvsurf_facs* facs,
                         Pint* tot_cat_len, Pint* tot_sat_len, Pint* tot_tcat_len, Pint* tot_psc_len);
void pset_dcue_rep(Pint ws_id, Pint dcue_ind, const Pdcue_bundle* dcue_rep);
void pinq_dcue_rep(Pint ws_id, Pint dcue_ind, Pinq_type type, Pint* err_ind, Pdcue_bundle* dcue_rep);
void pinq_list_dcue_inds(Pint ws_id, Pint num_elems_appl_list, Pint start_ind, Pint* err_ind,
                         Pint_list* dcue_inds, Pint* num_elems_impl_list);

/* ==== PHIGS PLUS primitives with data (polyline set, cell array plus, set of fill area sets),
 * rendering colour model and colour mapping ==== */
#define Pfn_polyline_set3_data (301)
#define Pfn_cell_array3_plus (303)
#define Pfn_set_of_fill_area_set3_data (304)
#define Pfn_set_rendering_colr_model (331)
#define Pfn_set_colr_map_rep (342)
/* POLYLINE SET 3 WITH DATA: npl polylines; vflag PVERT_COORD or PVERT_COORD_COLOUR (a colour at
 * every vertex: with polyline shading method PSD_NONE a segment is drawn in its first vertex's
 * colour, with PSD_COLOUR the colour goes linearly from one vertex's to the next along it, in
 * pieces within 1/255 of each other). */
void ppolyline_set3_data(Pint vflag, Pint colr_type, Pint npl, const Pline_vdata_list3* vdata);
/* CELL ARRAY 3 PLUS: dim->size_x columns x dim->size_y rows of general colours, row by row. */
void pcell_array3_plus(const Pparal* paral, const Pint_size* dim, Pint colr_type, const Pcoval* colrs);
/* SET OF FILL AREA SETS 3 WITH DATA: num_sets fill area sets whose contours (vlist[s]) index the
 * vertices of vdata (from 0); facet data one per set (fdata), edge flags one per contour vertex
 * (edata[s], edge k from vertex k to k + 1) when eflag is PEDGE_VISIBILITY. An index outside the
 * vertices or edge data shaped unlike the contours is -202. */
void pset_of_fill_area_set3_data(Pint fflag, Pint eflag, Pint vflag, Pint colr_type, Pint num_sets,
                                 const Pfacet_data_arr3* fdata, const Pedge_data_list_list* edata,
                                 const Pint_list_list* vlist, const Pfacet_vdata_list3* vdata);
/* SET RENDERING COLOUR MODEL: the colour space area primitives' colours are interpolated and depth
 * cued in, on every workstation type. Vertex colours, and with PSD_COLOUR shading the vertex
 * colours lit, are converted into the model (CIE: u', v', Y; HSV; HLS; components as for
 * pset_colr_model, the colour clamped to [0, 1] first), interpolated across the facet component
 * by component (hue linearly, without wrapping), depth cued there and converted back to RGB. The
 * reflectance equations sum in RGB (a product of hues has no meaning). The hardcopy types shade
 * per triangle of the area (a triangle is one): each shows its vertices' mean in the model, the
 * colour the raster shows at its centroid. PRCM_WS_DEP and any other value draw
 * as PRCM_RGB. Polylines, edges, markers and text are drawn in RGB. */
#define PRCM_WS_DEP 0
#define PRCM_RGB 1
#define PRCM_CIE 2
#define PRCM_HSV 3
#define PRCM_HLS 4
void pset_rendering_colr_model(Pint model);

/* Colour mapping (PHIGS PLUS). Each workstation has a colour mapping table of 20 entries; entry 0
 * is predefined TRUE, an undefined index maps as entry 0. TRUE draws colours as they are; PSEUDO
 * takes the components c of a colour in colr_model and draws colrs[round(v (n - 1))] (given in
 * colr_model) with v = clamp(weights . c, 0, 1); PSEUDO_N maps each component c of colr_model
 * through its list (list[round(c (n - 1))]) and draws the colour table entry at the rounded sum.
 * A colr_model outside PMODEL_RGB .. PMODEL_HLS is 110; the inquiries answer the model given. Colours are
 * mapped where traversal resolves them (after the colour table, before lighting), so an unlit primitive shows
 * exactly the mapped colour. */
#define PCOLR_MAP_TRUE 1
#define PCOLR_MAP_PSEUDO 2
#define PCOLR_MAP_PSEUDO_N 3
typedef struct {
    Pint num_colr_reps;
    Pcolr_rep* colr_reps;
} Pcolr_rep_list;
typedef struct {
    Pint num_lists;
    Pfloat_list* lists;
} Pfloat_list_list;
typedef union {
    struct {
        Pint colr_model;     /* PMODEL_RGB .. PMODEL_HLS */
        Pfloat_list weights; /* three */
        Pcolr_rep_list colrs;
    } meth_r2;
    struct {
        Pint colr_model;             /* PMODEL_RGB .. PMODEL_HLS */
        Pfloat_list_list colr_lists; /* three */
    } meth_r3;
} Pcolr_map_data;
typedef struct {
    Pint_list meths;
    Pint num_pred_inds;
} Pcolr_map_facs;
typedef struct {
    Pint int_data; /* colours available to the method */
} Pcolr_map_st;
/* SET COLOUR MAPPING REPRESENTATION (map_data may be NULL for TRUE): 121 index < 0, 103 table
 * full, 126 method not available, 110 colour model not RGB, 118 a colour component outside
 * [0, 1], -207 weights not three, no colours, or PSEUDO_N lists not three non-empty. Like every
 * representation it shows when the picture is regenerated (the deferral mode says when). */
void pset_colr_map_rep(Pint ws_id, Pint index, Pint map_method, const Pcolr_map_data* map_data);
/* The entry as set (PINQ_SET: 101 when undefined) or as used (PINQ_REALIZED: entry 0 for an
 * undefined index); the data of PSEUDO and PSEUDO_N points into the store. */
void pinq_colr_map_rep(Pint ws_id, Pint index, Pinq_type type, Pstore store, Pint* err_ind, Pint* map_method,
                       Pcolr_map_data** map_data);
void pinq_pred_colr_map_rep(Pint ws_type, Pint index, Pstore store, Pint* err_ind, Pint* map_method,
                            Pcolr_map_data** map_data);
void pinq_list_colr_map_inds(Pint ws_id, Pint num_elems_appl_list, Pint start_ind, Pint* err_ind,
                             Pint_list* inds, Pint* num_elems_impl_list);
/* The colours a method has on an open workstation (pinq_colr_map_st) or a type
 * (pinq_colr_map_method_facs): TRUE 2^24, PSEUDO and PSEUDO_N the colour table's size; 126 for
 * another method. The facilities list the three methods and one predefined entry. */
void pinq_colr_map_st(Pint ws_id, Pint map_method, Pint* err_ind, Pcolr_map_st* map_st);
void pinq_colr_map_facs(Pint ws_type, Pint num_elems_appl_list, Pint start_ind, Pint* err_ind,
                        Pcolr_map_facs* facs, Pint* num_elems_impl_list);
void pinq_colr_map_method_facs(Pint ws_type, Pint map_method, Pint* err_ind, Pcolr_map_st* map_st);

/* ---- PHIGS PLUS bundles: the extended polyline, polymarker, text, interior, edge and pattern
 * representations. One table per kind holds both views: pset_*_rep sets an entry with an
 * indexed colour (PINDIRECT) and the PHIGS PLUS fields at their defaults (shading PSD_NONE,
 * reflectance PREFL_NONE, approximation PCURV_WS_DEP / PSURF_WS_DEP with value 1, the back face
 * as the front); pinq_*_rep of an entry whose colour is direct answers 134. Colours are
 * PINDIRECT or PMODEL_RGB .. PMODEL_HLS (any other type: 110); errors 100 (index < 1; 112 for patterns), 103
 * (table full), 113 (an index < 0), 136 (a direct component outside [0, 1]), 104 .. 108 as the
 * plain functions, 122 polyline shading method, 123 interior shading method and 124 reflectance
 * equation not available. PINQ_REALIZED answers as the plain inquiries do (undefined index:
 * entry 1; undefined colour index: 1); the PHIGS PLUS fields as set. */
typedef struct {
    Pint type;
    Pfloat width;
    Pgcolr colr;
    Pint shad_meth;   /* PSD_NONE or PSD_COLOUR */
    Pint approx_type; /* curve approximation criteria (PCURV_*) and its value */
    Pfloat approx_val;
} Pline_bundle_plus;
typedef struct {
    Pint type;
    Pfloat size;
    Pgcolr colr;
} Pmarker_bundle_plus;
typedef struct {
    Pint font;
    Ptext_prec prec;
    Pfloat char_expan;
    Pfloat char_space;
    Pgcolr colr;
} Ptext_bundle_plus;
typedef struct {
    Pint_style style;
    Pint style_ind;
    Pgcolr colr;
    Pint refl_eqn;  /* PREFL_* */
    Pint shad_meth; /* PSD_* */
    Prefl_props refl_props;
    Pint_style back_style;
    Pint back_style_ind;
    Pgcolr back_colr;
    Pint back_refl_eqn;
    Pint back_shad_meth;
    Prefl_props back_refl_props;
    Pint approx_type; /* surface approximation criteria (PSURF_*) and its u and v values */
    Pfloat approx_val[2];
} Pint_bundle_plus;
typedef struct {
    Pedge_flag flag;
    Pint type;
    Pfloat width;
    Pgcolr colr;
} Pedge_bundle_plus;
/* A pattern of general colours: dims.size_x x dims.size_y cells, row by row, all of colour type
 * `type` (PINDIRECT: colr_array[i].ind; a colour model: colr_array[i].direct). */
typedef struct {
    Pint_size dims;
    Pint type;
    Pcoval* colr_array;
} Ppat_rep_plus;
/* Facilities: the line types and the polyline shading methods; the interior styles, hatch styles,
 * reflectance equations and interior shading methods (each a simple list of its own). */
typedef struct {
    Pint_list types;
    Pint num_widths; /* 0: continuous */
    Pfloat nom_width, min_width, max_width;
    Pint num_pred_inds;
    Pint_list shads;
} Pline_facs_plus;
typedef struct {
    Pint num_int_styles;
    Pint_style* int_styles;
    Pint_list hatch_styles;
    Pint num_pred_inds;
    Pint_list refl_eqns;
    Pint_list shad_meths;
} Pint_facs_plus;
/* Table lengths with the depth cue, light source and colour mapping tables; their dynamics. */
typedef struct {
    Pint line_bundles, mark_bundles, text_bundles, int_bundles, edge_bundles, pat_reps, colr_reps, view_reps;
    Pint dcue_rep, light_src_rep, colr_map_rep;
} Pws_tables_plus;
typedef struct {
    Pdyn_mod light_src_rep, dcue_rep, colr_map_rep;
} Pdyns_ws_attrs_plus;
#define Pfn_set_line_rep_plus (334)
#define Pfn_set_marker_rep_plus (335)
#define Pfn_set_text_rep_plus (336)
#define Pfn_set_int_rep_plus (337)
#define Pfn_set_edge_rep_plus (338)
#define Pfn_set_pat_rep_plus (339)
void pset_line_rep_plus(Pint ws_id, Pint line_ind, const Pline_bundle_plus* line_rep);
void pset_marker_rep_plus(Pint ws_id, Pint marker_ind, const Pmarker_bundle_plus* marker_rep);
void pset_text_rep_plus(Pint ws_id, Pint text_ind, const Ptext_bundle_plus* text_rep);
void pset_int_rep_plus(Pint ws_id, Pint int_ind, const Pint_bundle_plus* int_rep);
void pset_edge_rep_plus(Pint ws_id, Pint edge_ind, const Pedge_bundle_plus* edge_rep);
void pset_pat_rep_plus(Pint ws_id, Pint pat_ind, const Ppat_rep_plus* pat_rep);
void pinq_line_rep_plus(Pint ws_id, Pint line_ind, Pinq_type type, Pint* err_ind,
                        Pline_bundle_plus* line_rep);
void pinq_marker_rep_plus(Pint ws_id, Pint marker_ind, Pinq_type type, Pint* err_ind,
                          Pmarker_bundle_plus* marker_rep);
void pinq_text_rep_plus(Pint ws_id, Pint text_ind, Pinq_type type, Pint* err_ind,
                        Ptext_bundle_plus* text_rep);
void pinq_int_rep_plus(Pint ws_id, Pint int_ind, Pinq_type type, Pint* err_ind, Pint_bundle_plus* int_rep);
void pinq_edge_rep_plus(Pint ws_id, Pint edge_ind, Pinq_type type, Pint* err_ind,
                        Pedge_bundle_plus* edge_rep);
/* The pattern lives in `store` (its colours too) until the store's next use. */
void pinq_pat_rep_plus(Pint ws_id, Pint pat_ind, Pinq_type type, Pstore store, Pint* err_ind,
                       Ppat_rep_plus** pat_rep);
/* Predefined representations of a type (the plain ones' entries with indexed colours): 52 for an
 * unknown type, 100 (112 for patterns) below 1, 102 past the last. */
void pinq_pred_line_rep_plus(Pint ws_type, Pint line_ind, Pint* err_ind, Pline_bundle_plus* line_rep);
void pinq_pred_marker_rep_plus(Pint ws_type, Pint marker_ind, Pint* err_ind, Pmarker_bundle_plus* marker_rep);
void pinq_pred_text_rep_plus(Pint ws_type, Pint text_ind, Pint* err_ind, Ptext_bundle_plus* text_rep);
void pinq_pred_int_rep_plus(Pint ws_type, Pint int_ind, Pint* err_ind, Pint_bundle_plus* int_rep);
void pinq_pred_edge_rep_plus(Pint ws_type, Pint edge_ind, Pint* err_ind, Pedge_bundle_plus* edge_rep);
void pinq_pred_pat_rep_plus(Pint ws_type, Pint pat_ind, Pstore store, Pint* err_ind, Ppat_rep_plus** pat_rep);
/* Each list answers as a simple list (2201, 2200); int_styles must have room for is_length. */
void pinq_line_facs_plus(Pint ws_type, Pint lt_length, Pint lt_start, Pint sm_length, Pint sm_start,
                         Pint* err_ind, Pint* tot_lt_length, Pint* tot_sm_length, Pline_facs_plus* facs);
void pinq_int_facs_plus(Pint ws_type, Pint is_length, Pint is_start, Pint hs_length, Pint hs_start,
                        Pint re_length, Pint re_start, Pint sh_length, Pint sh_start, Pint* err_ind,
                        Pint_facs_plus* facs, Pint* tot_is_length, Pint* tot_hs_length, Pint* tot_re_length,
                        Pint* tot_sh_length);
void pinq_ws_st_table_plus(Pint ws_type, Pint* err_ind, Pws_tables_plus* lengths);
void pinq_dyns_ws_attrs_plus(Pint ws_type, Pint* err_ind, Pdyns_ws_attrs_plus* attrs);

#ifdef __cplusplus
}
#endif

#endif /* PHIGS_C_BINDING_H */
