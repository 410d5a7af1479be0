#pragma once

// Pstore (ISO 9593-4): the memory of one variable-size inquiry answer. Each inquiry that is
// given the store replaces what it held, so answers stay valid until the store's next use.

#include "InputAnswer.h"
#include "phigs.h"

#include <string>
#include <vector>

/// What an inquiry answer points into (the C binding's opaque Pstore).
struct Phigs_store {
    Pelem_data data{};
    std::vector<Ppoint3> points3;
    std::vector<Ppoint> points;
    std::vector<Ppoint_list3> lists3;
    std::vector<Ppoint_list> lists;
    std::vector<Pint> ints;
    std::vector<Phalf_space3> halfSpaces3;
    std::vector<Phalf_space> halfSpaces;
    std::string text;
    std::vector<Pelem_ref> refs;
    std::vector<Pelem_ref_list> refLists;
    Pelem_ref_list_list paths{};
    std::vector<std::string> names;
    std::vector<Par_file> files;
    Par_file_list fileList{};
    // Workstation answers: a filter's two name sets and a pattern, their ints in `ints`.
    Pfilter filter{};
    Ppat_rep pattern{};
    Ppat_rep_plus patternPlus{};  ///< its colours in `covals`
    std::vector<Pcoval> covals;   ///< also the cells of a cell array plus
    phigs::c::InputAnswer input;  ///< the input inquiries' answers
    std::vector<Pfloat> floats;   // PHIGS PLUS: knots
    std::vector<Ppoint4> points4;
    std::vector<Ptrimcurve> trimCurves;
    std::vector<Ptrimcurve_list> trimLoops;
    std::vector<Pptco3> ptcolrs;
    std::vector<Pptnorm3> ptnorms;
    std::vector<Pptconorm3> ptconorms;
    std::vector<Pfacet_vdata_list3> vertexLists;
    // Polyline sets, cell arrays plus, sets of fill area sets, colour mapping answers.
    std::vector<Pline_vdata_list3> lineLists;
    std::vector<Pvec3> norms;
    std::vector<Pconorm3> conorms;
    std::vector<Pint_list> intLists;
    std::vector<Pint_list_list> intListLists;
    std::vector<Pedge_flag> edgeFlags;
    std::vector<Pedge_data_list> edgeLists;
    std::vector<Pedge_data_list_list> edgeListLists;
    Pcolr_map_data colourMap{};
    std::vector<Pcolr_rep> colourReps;
    std::vector<Pfloat_list> floatLists;

    /// Forgets the previous answer (its memory is reused).
    void clear() {
        data = {};
        points3.clear(), points.clear(), lists3.clear(), lists.clear(), ints.clear();
        halfSpaces3.clear(), halfSpaces.clear(), text.clear();
        refs.clear(), refLists.clear(), paths = {};
        names.clear(), files.clear(), fileList = {};
        filter = {}, pattern = {}, patternPlus = {}, covals.clear();
        input = {};
        floats.clear(), points4.clear(), trimCurves.clear(), trimLoops.clear();
        ptcolrs.clear(), ptnorms.clear(), ptconorms.clear(), vertexLists.clear();
        lineLists.clear(), norms.clear(), conorms.clear();
        intLists.clear(), intListLists.clear(), edgeFlags.clear(), edgeLists.clear(), edgeListLists.clear();
        colourMap = {}, colourReps.clear(), floatLists.clear();
    }
};
