#pragma once
// The characters the viewer's font must hold (Dear ImGui glyph ranges: pairs of first and last
// code point, ending in 0): Latin-1 for Spanish (á é í ó ú ñ ü ¿ ¡ º ª ·), Greek for the
// formulas' θ α ρ π, the subscript i and the super- and subscripts, and the maths signs Σ ∫ ≈.
// Plain unsigned shorts, ImGui's ImWchar16, so that a test can check them without a window.
namespace luz::app {

inline constexpr unsigned short kUiGlyphRanges[] = {
    0x0020, 0x00FF,  // Basic Latin and Latin-1 Supplement
    0x0370, 0x03FF,  // Greek
    0x1D62, 0x1D62,  // subscript i
    0x2070, 0x209F,  // superscripts and subscripts
    0x2200, 0x22FF,  // mathematical operators
    0,
};

}  // namespace luz::app
