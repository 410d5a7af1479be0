#pragma once

// The memory of an input inquiry's answer inside a Pstore (device states, default data).

#include "phigs.h"

#include <string>
#include <vector>

namespace phigs::c {

/// What an input inquiry's answer points into: data records, the initial stroke, pick path
/// and filter, choice prompts and strings, the prompt/echo types.
struct InputAnswer {
    Ploc_data3 loc{};
    Pstroke_data3 stroke3{};
    Pstroke_data stroke{};
    Pval_data3 val{};
    Pchoice_data3 choice{};
    Ppick_data3 pick{};
    Pstring_data3 string{};
    Ppoint_list3 points3{};
    Ppoint_list points{};
    std::vector<Ppoint3> points3Memory;
    std::vector<Ppoint> pointsMemory;
    Pfilter filter{};
    std::vector<Pint> inclusion, exclusion;
    Ppick_path path{};
    std::vector<Ppick_path_elem> pathItems;
    std::vector<Ppr_switch> prompts;
    std::vector<std::string> strings;
    std::vector<char*> stringPointers;
    std::string text;
    Pint_list pets{};
    std::vector<Pint> petMemory;
};

}  // namespace phigs::c
