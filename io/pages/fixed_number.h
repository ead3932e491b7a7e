// Numbers as the vector formats (SVG, PDF) take them: a point for the decimal, no exponent.
#pragma once

#include <string>

namespace tsk::io {

// Appends `value` with three decimals, exactly as printf's "%.3f" writes it in the C locale
// (the exact binary value rounded to nearest, ties to even; "-0.000" for a negative value that
// rounds to zero). Most values take a fast path: a page of a million paths has tens of millions.
void append_fixed3(std::string& out, double value);

}  // namespace tsk::io
