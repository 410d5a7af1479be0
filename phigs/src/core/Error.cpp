#include "phigs/core/Error.h"

#include "phigs/core/ErrorLog.h"

#include <map>

namespace phigs {

namespace {

const std::map<int, const char*>& messages() {
    static const std::map<int, const char*> table = {
        {1, "Ignoring function, function requires state (PHCL, WSCL, STCL, ARCL)"},
        {2, "Ignoring function, function requires state (PHOP, *, *, *)"},
        {3, "Ignoring function, function requires state (PHOP, WSOP, *, *)"},
        {4, "Ignoring function, function requires state (PHOP, WSCL, STCL, ARCL)"},
        {5, "Ignoring function, function requires state (PHOP, *, STOP, *)"},
        {6, "Ignoring function, function requires state (PHOP, *, STCL, *)"},
        {7, "Ignoring function, function requires state (PHOP, *, *, AROP)"},
        {50, "Ignoring function, connection identifier not recognized by the implementation"},
        {52, "Ignoring function, workstation type not recognized by the implementation"},
        {53, "Ignoring function, workstation identifier already is in use"},
        {54, "Ignoring function, the specified workstation is not open"},
        {55, "Ignoring function, workstation cannot be opened for an implementation dependent reason"},
        {59, "Ignoring function, the specified workstation does not have output capability"},
        {60, "Ignoring function, specified workstation is not of category OUTIN"},
        {61, "Ignoring function, specified workstation is neither of category INPUT nor of category OUTIN"},
        {64,
         "Ignoring function, the specified workstation type is not able to generate the specified "
         "generalized drawing primitive"},
        {100, "Ignoring function, the bundle index value is less than one"},
        {101, "Ignoring function, the specified representation has not been defined"},
        {102, "Ignoring function, the specified representation has not been predefined on this workstation"},
        {103,
         "Ignoring function, setting this bundle table entry would exceed the maximum number of entries "
         "allowed in the workstation bundle table"},
        {104, "Ignoring function, the specified linetype is not available on the specified workstation"},
        {105, "Ignoring function, the specified marker type is not available on the specified workstation"},
        {106,
         "Ignoring function, the specified font is not available for the requested text precision on "
         "the specified workstation"},
        {107, "Ignoring function, the specified edgetype is not available on the specified workstation"},
        {108, "Ignoring function, the specified interior style is not available on the workstation"},
        {110, "Ignoring function, the specified colour model is not available on the workstation"},
        {111, "Ignoring function, the specified HLHSR mode is not available on the specified workstation"},
        {112, "Ignoring function, the pattern index value is less than one"},
        {113, "Ignoring function, the colour index value is less than zero"},
        {114, "Ignoring function, the view index value is less than zero"},
        {115, "Ignoring function, the view index value is less than one"},
        {116, "Ignoring function, one of the dimensions of pattern colour index array is less than one"},
        {118, "Ignoring function, one of the components of the colour specification is out of range"},
        {119, "Ignoring function, the depth cue index value is less than zero"},
        {121, "Ignoring function, the colour mapping index value is less than zero"},
        {126, "Ignoring function, the specified colour mapping method is not available on the workstation"},
        {122, "Ignoring function, the specified polyline shading method is not available on the workstation"},
        {123, "Ignoring function, the specified interior shading method is not available on the workstation"},
        {124,
         "Ignoring function, the specified interior reflectance equation is not available on the "
         "workstation"},
        {134,
         "Ignoring function, the requested entry contains a general colour specification with colour type "
         "other than INDIRECT"},
        {136, "Ignoring function, one of the components of the colour specification is out of range"},
        {150,
         "Ignoring function, setting this view table entry would exceed the maximum number of entries "
         "allowed in the workstation's view table"},
        {151, "Ignoring function, invalid window; XMIN >= XMAX, YMIN >= YMAX, or ZMIN > ZMAX"},
        {152, "Ignoring function, invalid viewport; XMIN >= XMAX, YMIN >= YMAX, or ZMIN > ZMAX"},
        {153, "Ignoring function, invalid view clipping limits; XMIN >= XMAX, YMIN >= YMAX, or ZMIN > ZMAX"},
        {154, "Ignoring function, the view clipping limits are not within NPC range"},
        {155, "Ignoring function, the projection viewport limits are not within NPC range"},
        {156, "Ignoring function, the workstation window limits are not within NPC range"},
        {157, "Ignoring function, the workstation viewport is not within display space"},
        {158,
         "Ignoring function, front plane and back plane distances are equal when z-extent of the "
         "projection viewport is non-zero"},
        {159, "Ignoring function, the view plane normal vector has length zero"},
        {160, "Ignoring function, the view up vector has length zero"},
        {161,
         "Ignoring function, the view up and view plane normal vectors are parallel thus the viewing "
         "coordinate system cannot be established"},
        {162, "Ignoring function, the projection reference point is between the front and back planes"},
        {163, "Ignoring function, the projection reference point cannot be positioned on the view plane"},
        {164, "Ignoring function, the back plane is in front of the front plane"},
        {200, "Warning, ignoring structures that do not exist"},
        {201, "Ignoring function, the specified structure does not exist"},
        {202, "Ignoring function, the specified element does not exist"},
        {203, "Ignoring function, specified starting path not found in CSS"},
        {204, "Ignoring function, specified search ceiling index out of range"},
        {205,
         "Ignoring function, the label does not exist in the open structure between the element pointer "
         "and the end of the structure"},
        {206,
         "Ignoring function, one or both of the labels does not exist in the open structure between the "
         "element pointer and the end of the structure"},
        {207, "Ignoring function, the specified path depth is less than zero (0)"},
        {208, "Ignoring function, the display priority is out of range"},
        {250, "Ignoring function, the specified device is not available on the specified workstation"},
        {251, "Ignoring function, the function requires the input device to be in REQUEST mode"},
        {252, "Ignoring function, the function requires the input device to be in SAMPLE mode"},
        {253,
         "Warning, the specified prompt/echo type is not available on the specified workstation. "
         "Prompt/echo type one will be used in its place"},
        {254, "Ignoring function, invalid echo area/volume; XMIN >= XMAX, YMIN >= YMAX, or ZMIN > ZMAX"},
        {255,
         "Ignoring function, one of the echo area/volume boundary points is outside the range of the "
         "device"},
        {256, "Warning, the input queue has overflowed"},
        {257,
         "Ignoring function, input queue has not overflowed since PHIGS was opened or the last invocation "
         "of INQUIRE INPUT QUEUE OVERFLOW"},
        {258, "Ignoring function, input queue has overflowed, but associated workstation has been closed"},
        {259,
         "Ignoring function, the input device class of the current input report does not match the class "
         "being requested"},
        {260, "Ignoring function, one of the fields within the input device data record is in error"},
        {261, "Ignoring function, the initial value is invalid"},
        {262, "Ignoring function, number of points in the initial stroke is greater than the buffer size"},
        {263, "Ignoring function, length of the initial string is greater than the buffer size"},
        {400, "Ignoring function, the archive file cannot be opened"},
        {402, "Ignoring function, archive file identifier already in use"},
        {403, "Ignoring function, the archive file is not a PHIGS archive file"},
        {404, "Ignoring function, the specified archive file is not open"},
        {405, "Ignoring function, name conflict occurred while conflict resolution flag has value ABANDON"},
        {407, "Warning, some of the specified structures do not exist on the archive file"},
        {408,
         "Warning, some of the specified structures do not exist on the archive file. PHIGS will create "
         "empty structures in their places"},
        {350,
         "Warning, the specified escape is not available on one or more workstations in this implementation"},
        {351, "Ignoring function, one of the fields within the escape data record is in error"},
        {900, "Storage overflow has occurred in PHIGS"},
        {903, "Input/Output error has occurred while writing"},
        {908, "Arithmetic error has occurred"},
        {2200, "Start index out of range"},
        {2201, "The length of the application's list is negative"},
        {2202, "Enumeration type out of range"},
        {2203, "Error while allocating a Store"},
        {2204, "Error while allocating memory for a Store"},
        {-201, "Ignoring function, executing this structure would make the structure network cyclic"},
        {-202, "Ignoring function, the element data is invalid"},
        {-203, "Ignoring function, the structure network is nested too deeply"},
        {-204, "Ignoring function, a required argument is a null pointer or a negative count"},
        {-205, "The element's content has no C binding form in this implementation"},
        {-206, "Ignoring function, the input script ended while a REQUEST waits for input"},
        {-207, "Ignoring function, the colour mapping data record is invalid for its method"},
    };
    return table;
}

std::string composeWhat(int number, const std::string& function, const std::string& detail) {
    std::string what =
        "PHIGS error " + std::to_string(number) + " in " + function + ": " + errorMessage(number);
    if (!detail.empty()) what += " (" + detail + ")";
    return what;
}

}  // namespace

Error::Error(int number, std::string function, std::string detail)
    : std::runtime_error(composeWhat(number, function, detail)),
      number_(number),
      function_(std::move(function)),
      detail_(std::move(detail)) {
}

std::string errorMessage(int number) {
    const auto& table = messages();
    auto found = table.find(number);
    return found != table.end() ? found->second : "PHIGS error";
}

std::string ErrorLog::text() const {
    std::string out;
    for (const Entry& entry : entries_) {
        out +=
            (entry.number >= 200 && entry.number < 1000 && errorMessage(entry.number).starts_with("Warning")
                 ? "WARNING "
                 : "ERROR ");
        out += std::to_string(entry.number) + " in " + entry.function + ": " + errorMessage(entry.number);
        if (!entry.detail.empty()) out += " (" + entry.detail + ")";
        out += '\n';
    }
    return out;
}

void raise(ErrorLog* log, int number, const char* function, std::string detail) {
    Error error(number, function, std::move(detail));
    if (log) log->record(error);
    throw error;
}

}  // namespace phigs
