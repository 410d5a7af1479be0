#pragma once

// The error numbers (ISO 9592) of the workstation's representations and description table,
// beyond the common ones of phigs/core/Error.h.

namespace phigs::errors {

inline constexpr int RepresentationNotPredefined = 102;  ///< no such predefined representation
inline constexpr int TextFontNotAvailable = 106;         ///< font and precision pair not available
inline constexpr int EdgeTypeNotAvailable = 107;
inline constexpr int ColourModelNotAvailable = 110;
inline constexpr int BadPatternDimensions = 116;         ///< a dimension of the colour index array below one
inline constexpr int PolylineShadingNotAvailable = 122;  ///< PHIGS PLUS
inline constexpr int InteriorShadingNotAvailable = 123;
inline constexpr int ReflectanceNotAvailable = 124;
inline constexpr int NotIndirectColour = 134;  ///< the entry's general colour is not an index

}  // namespace phigs::errors
