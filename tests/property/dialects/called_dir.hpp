// A directory of its own for the files a test program calls (a call of another file), removed
// when the test ends.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

struct called_dir {
  std::filesystem::path path;
  explicit called_dir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / ("kin5-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~called_dir() { std::filesystem::remove_all(path); }
  called_dir(const called_dir&) = delete;
  called_dir& operator=(const called_dir&) = delete;
  void write(const std::string& name, const std::string& text) const { std::ofstream(path / name, std::ios::binary) << text; }
};
