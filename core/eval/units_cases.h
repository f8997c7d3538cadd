// The curated real objects of dataset folders as cases for the size memory
// (core/annotate/size_memory.h, core/eval/size_memory_loso.h): each object's file read as
// `annotate` reads it (the up axis its provenance declares, else detected), its largest extent in
// file units, its descriptor with the models' feature configuration, its curated units, category
// ("stove", "sink", else "none") and source (core/dataset/object_source.h).
#pragma once

#include <filesystem>
#include <functional>
#include <vector>

#include "core/eval/size_memory_loso.h"
#include "core/features/feature_pipeline.h"

namespace sagrid {

// `progress(done, total, id)` after each object. An object whose labels still hold an unconfirmed
// units guess (core/annotate/units_record.h: nobody set or confirmed its units) is no curated size
// and is left out, counted in `unconfirmed` where given. Throws FileError naming the object whose
// mesh or labels cannot be read; a folder with no objects gives none.
std::vector<UnitsCase> readUnitsCases(
    const std::vector<std::filesystem::path>& dataFolders, const FeatureOptions& options,
    const std::function<void(std::size_t, std::size_t, const std::string&)>& progress = {},
    std::size_t* unconfirmed = nullptr);

}  // namespace sagrid
