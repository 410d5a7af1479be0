#include "Units.h"

#include "geom/exchange/CadModel.h"

#include <algorithm>
#include <cctype>
#include <initializer_list>

namespace geom::exchange {

namespace {

/// One length unit: OpenCASCADE's code (a value its unit settings accept: inches are "INCH", and
/// a code they refuse leaves the unit before in place), its size and the spellings files use
/// (lower case).
struct UnitName {
    const char* code;
    double metres;
    std::initializer_list<const char*> names;
};

const UnitName units[] = {
    {"M", 1.0, {"m", "metre", "meter", "metres", "meters"}},
    {"MM", 1e-3, {"mm", "millimetre", "millimeter", "millimetres", "millimeters"}},
    {"CM", 1e-2, {"cm", "centimetre", "centimeter", "centimetres", "centimeters"}},
    {"KM", 1e3, {"km", "kilometre", "kilometer", "kilometres", "kilometers"}},
    {"UM", 1e-6, {"um", "micrometre", "micrometer", "micron", "microns"}},
    {"INCH", 0.0254, {"in", "inch", "inches"}},
    {"FT", 0.3048, {"ft", "foot", "feet"}},
    {"MI", 1609.344, {"mi", "mile", "miles"}},
    {"MIL", 2.54e-5, {"mil", "mils"}},
    {"UIN", 2.54e-8, {"uin", "microinch", "microinches"}},
};

const UnitName* find(const std::string& name) {
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    for (const UnitName& u : units)
        for (const char* n : u.names)
            if (lower == n) return &u;
    return nullptr;
}

}  // namespace

std::optional<std::string> occtUnitCode(const std::string& unitName) {
    const UnitName* u = find(unitName);
    return u ? std::optional<std::string>(u->code) : std::nullopt;
}

std::optional<double> metresPerUnit(const std::string& unitName) {
    const UnitName* u = find(unitName);
    return u ? std::optional<double>(u->metres) : std::nullopt;
}

}  // namespace geom::exchange
