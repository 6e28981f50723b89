// Errors raised when a file cannot be read or written (by core/io, and by
// write_file_atomically for every part). Each names the file and, for JSON
// input, the JSON pointer of the offending value.
#pragma once

#include <stdexcept>
#include <string>

namespace procex {

class IoError : public std::runtime_error {
 public:
  // what: the full message (already naming path and pointer); path: the file;
  // pointer: RFC 6901 JSON pointer ("" for the whole document or non-JSON files).
  IoError(const std::string& what, std::string path, std::string pointer = {})
      : std::runtime_error(what), path_(std::move(path)), pointer_(std::move(pointer)) {}
  const std::string& path() const { return path_; }
  const std::string& pointer() const { return pointer_; }

 private:
  std::string path_;
  std::string pointer_;
};

}  // namespace procex
