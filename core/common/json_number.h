// A float as the double JSON writes, rounded to 7 significant digits (what a float holds), so
// 0.2f reads 0.2 and not 0.20000000298023224.
#pragma once

namespace sagrid {

double jsonNumber(float value);

}  // namespace sagrid
