// Error types of sagrid_core. Core never prints and never exits: it throws one of these with a
// message meant for the user (which file, what is wrong, what to do); main and the GUI decide how
// to show it.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace sagrid {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file or directory the user named cannot be used: missing, unreadable, corrupt, wrong format.
// The message always starts with the path.
class FileError : public Error {
 public:
  FileError(const std::filesystem::path& path, const std::string& problem)
      : Error(path.string() + ": " + problem), m_path(path) {}
  const std::filesystem::path& path() const { return m_path; }

 private:
  std::filesystem::path m_path;
};

// A value the user gave (option, architecture string, field) is invalid.
class InvalidArgument : public Error {
 public:
  using Error::Error;
};

// A model, its card and the features in use do not fit together.
class ModelError : public Error {
 public:
  using Error::Error;
};

// Long work stopped because the user asked it to.
class Cancelled : public Error {
 public:
  Cancelled() : Error("cancelled") {}
};

}  // namespace sagrid
