// Helper process of kill_during_save_test: saves a project to argv[1] over and over, alternating
// between two versions (name "A" with a large description, name "B" with another one), until it is
// killed. Each save goes through saveProject (temporary file in the same folder, fsync, rename).
#include <cstdio>
#include <exception>
#include <string>

#include "core/project/project.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: save_loop PROJECT\n");
    return 2;
  }
  metrofit::Project a, b;
  a.name = "A";
  a.description = std::string(400000, 'a');  // large enough that a save takes a while
  b.name = "B";
  b.description = std::string(300000, 'b');
  try {
    for (unsigned long i = 0;; ++i) metrofit::saveProject(i % 2 ? b : a, argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "save_loop: %s\n", e.what());
    return 1;
  }
}
