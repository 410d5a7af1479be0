#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace phigs {

/// A PHIGS error: the ISO 9592 error number, the PHIGS function that detected it and, where it
/// helps, what exactly was wrong (file and line, the offending value).
class Error : public std::runtime_error {
public:
    Error(int number, std::string function, std::string detail = {});

    int number() const { return number_; }
    const std::string& function() const { return function_; }
    const std::string& detail() const { return detail_; }

private:
    int number_;
    std::string function_;
    std::string detail_;
};

/// The standard's text for an error number ("Ignoring function, ..."), or a generic text.
std::string errorMessage(int number);

/// The deepest nesting of EXECUTE STRUCTURE that traversal and the path inquiries follow.
inline constexpr std::size_t kMaxNetworkDepth = 1000;

/// ISO 9592 error numbers used by this implementation (negative: implementation-defined).
namespace errors {
inline constexpr int NotPhigsClosed = 1;            ///< requires (PHCL, WSCL, STCL, ARCL)
inline constexpr int NotPhigsOpen = 2;              ///< requires (PHOP, *, *, *)
inline constexpr int NoWorkstationOpen = 3;         ///< requires (PHOP, WSOP, *, *)
inline constexpr int NotAllClosed = 4;              ///< requires (PHOP, WSCL, STCL, ARCL)
inline constexpr int NotStructureOpen = 5;          ///< requires (PHOP, *, STOP, *)
inline constexpr int NotStructureClosed = 6;        ///< requires (PHOP, *, STCL, *)
inline constexpr int NoArchiveOpen = 7;             ///< requires (PHOP, *, *, AROP)
inline constexpr int ConnectionNotRecognized = 50;  ///< connection identifier not usable
inline constexpr int BadWorkstationType = 52;       ///< workstation type not recognized
inline constexpr int WorkstationIdInUse = 53;
inline constexpr int WorkstationNotOpen = 54;
inline constexpr int WorkstationCannotOpen = 55;  ///< the target could not be made
inline constexpr int NoOutputCapability = 59;
inline constexpr int GdpNotAvailable = 64;  ///< the workstation type cannot draw that GDP
inline constexpr int BundleIndexBelowOne = 100;
inline constexpr int RepresentationNotDefined = 101;
inline constexpr int BundleTableFull = 103;
inline constexpr int BadLineType = 104;
inline constexpr int BadMarkerType = 105;
inline constexpr int BadInteriorStyle = 108;
inline constexpr int BadHlhsrMode = 111;
inline constexpr int PatternIndexBelowOne = 112;
inline constexpr int ColourIndexBelowZero = 113;
inline constexpr int ViewIndexBelowZero = 114;
inline constexpr int ViewIndexBelowOne = 115;
inline constexpr int BadColour = 118;
inline constexpr int DepthCueIndexBelowZero = 119;           ///< PHIGS PLUS
inline constexpr int ColourMappingIndexBelowZero = 121;      ///< PHIGS PLUS
inline constexpr int ColourMappingMethodNotAvailable = 126;  ///< PHIGS PLUS
inline constexpr int BadDirectColour = 136;  ///< a direct colour component outside its model's range
inline constexpr int ViewTableFull = 150;
inline constexpr int InvalidWindow = 151;
inline constexpr int InvalidViewport = 152;
inline constexpr int InvalidClipLimits = 153;
inline constexpr int ClipLimitsOutsideNpc = 154;
inline constexpr int ProjectionViewportOutsideNpc = 155;
inline constexpr int WorkstationWindowOutsideNpc = 156;
inline constexpr int WorkstationViewportOutsideDisplay = 157;
inline constexpr int FrontEqualsBack = 158;
inline constexpr int ZeroViewPlaneNormal = 159;
inline constexpr int ZeroViewUp = 160;
inline constexpr int ViewUpParallelToNormal = 161;
inline constexpr int PrpBetweenPlanes = 162;
inline constexpr int PrpOnViewPlane = 163;
inline constexpr int BackInFrontOfFront = 164;
inline constexpr int IgnoringMissingStructures = 200;  ///< warning
inline constexpr int StructureDoesNotExist = 201;
inline constexpr int ElementDoesNotExist = 202;
inline constexpr int PathNotFound = 203;
inline constexpr int CeilingOutOfRange = 204;
inline constexpr int LabelNotFound = 205;
inline constexpr int LabelsNotFound = 206;
inline constexpr int NegativePathDepth = 207;
inline constexpr int BadDisplayPriority = 208;
inline constexpr int DeviceNotAvailable = 250;  ///< no such logical input device
inline constexpr int NotRequestMode = 251;      ///< the device must be in REQUEST mode
inline constexpr int NotSampleMode = 252;       ///< the device must be in SAMPLE mode
inline constexpr int BadPromptEchoType = 254;
inline constexpr int InvalidEchoArea = 255;
inline constexpr int InputQueueOverflowed = 256;  ///< warning
inline constexpr int InputQueueNotOverflowed = 257;
inline constexpr int OverflowWorkstationClosed = 258;  ///< the overflow's workstation has closed
inline constexpr int InputClassMismatch = 259;         ///< the current event report is of another class
inline constexpr int BadInputDataRecord = 260;
inline constexpr int BadInitialValue = 261;
inline constexpr int StrokeBufferTooSmall = 262;
inline constexpr int StringBufferTooSmall = 263;
inline constexpr int EscapeNotAvailable = 350;  ///< warning: no such escape in this implementation
inline constexpr int ArchiveCannotOpen = 400;
inline constexpr int ArchiveIdInUse = 402;
inline constexpr int NotAnArchive = 403;
inline constexpr int ArchiveNotOpen = 404;
inline constexpr int ArchiveNameConflict = 405;
inline constexpr int MissingInArchive = 407;              ///< warning
inline constexpr int MissingInArchiveCreatedEmpty = 408;  ///< warning: RETRIEVE made them empty
inline constexpr int StorageOverflow = 900;  ///< an answer would exceed the implementation's limits
inline constexpr int WriteError = 903;
inline constexpr int StructureCycle = -201;        ///< execute structure would make the network cyclic
inline constexpr int InvalidElementData = -202;    ///< element contents break the primitive's rules
inline constexpr int NetworkTooDeep = -203;        ///< more nested executes than kMaxNetworkDepth
inline constexpr int BadColourMappingData = -207;  ///< a colour mapping data record breaks its method's rules
inline constexpr int NonFiniteValue =
    -208;  ///< a real in a representation, view matrix or view utility's input is NaN or infinite
}  // namespace errors

}  // namespace phigs
