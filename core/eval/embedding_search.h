// The Embedding Search baseline of the paper's Table II: the mean per-voxel feature at the
// training objects' affordance positions (stored in the model card), and at inference the
// occupied voxel whose feature is most similar to it (cosine) or closest (L2).
#pragma once

#include <cstddef>
#include <vector>

namespace sagrid {

struct FeatureGrid;

enum class EmbeddingMetric { Cosine, L2 };

// Index into features.voxels of the best-matching voxel. Throws InvalidArgument when the
// feature length differs from the mean's or the grid is empty.
std::size_t embeddingSearchVoxel(const FeatureGrid& features,
                                 const std::vector<float>& affordanceMean, EmbeddingMetric metric);

}  // namespace sagrid
