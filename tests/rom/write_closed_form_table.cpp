// rom-closed-form-table: writes the docs/physics.md §2 closed-form mode table of a sphere or a spheroid
// (used by the command-line tests and the example scenes in data/scenes/).
//   rom-closed-form-table sphere R OUT.h5
//   rom-closed-form-table spheroid a c OUT.h5
#include "closed_form_tables.hpp"

#include <iostream>
#include <string>

int main(int argc, char** argv) {
  try {
    const std::string kind = argc > 1 ? argv[1] : "";
    if (kind == "sphere" && argc == 4) {
      rc::rom::test::write_table(rc::rom::test::sphere_table(std::stod(argv[2])), argv[3]);
    } else if (kind == "spheroid" && argc == 5) {
      rc::rom::test::write_table(rc::rom::test::spheroid_table(std::stod(argv[2]), std::stod(argv[3])), argv[4]);
    } else {
      std::cerr << "usage: rom-closed-form-table sphere R OUT.h5 | spheroid a c OUT.h5\n";
      return 1;
    }
  } catch (const std::exception& e) {
    std::cerr << "rom-closed-form-table: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
