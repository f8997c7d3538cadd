// How many worker threads CPU-parallel work uses: SAGRID_THREADS when set to a positive number
// (e.g. to run two trainings side by side, one core each), else the hardware threads.
#pragma once

namespace sagrid {

int defaultThreadCount();

}  // namespace sagrid
