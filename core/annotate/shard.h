// Splitting a collection into N shards for array jobs (`sagrid annotate --shard I/N`). An object
// belongs to shard (first 8 bytes of sha256(object id)) mod N: the split depends on the id alone,
// not on directory order, the file system or which other objects exist, so every task of an array
// computes the same split and a folder that gains objects keeps the old objects' shards.
#pragma once

#include <string>
#include <vector>

#include "core/mesh/mesh_files.h"

namespace sagrid {

struct Shard {
  int index = 0;  // 0 <= index < count
  int count = 1;

  bool contains(const std::string& objectId) const;
  std::string toString() const;  // "I/N"
};

// "I/N" with 0 <= I < N (a Slurm array task's id and the array's size); throws InvalidArgument
// naming the spec and the rule for anything else (5/4, 0/0, -1/3, 1/x, ...).
Shard parseShard(const std::string& spec);

// The files whose object id falls in `shard`, in their original order.
std::vector<MeshFile> filesInShard(const std::vector<MeshFile>& files, const Shard& shard);

}  // namespace sagrid
