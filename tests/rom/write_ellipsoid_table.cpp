// rom-ellipsoid-table: writes the triaxial ellipsoid's closed-form 3-D table (ellipsoid_table.hpp), the reference the
// command-line test compares a cavity-modes ellipsoid table's chain roots with.
//   rom-ellipsoid-table a b c TILT_DEG OUT.h5
#include "ellipsoid_table.hpp"

#include <iostream>
#include <numbers>
#include <string>

int main(int argc, char** argv) {
  if (argc != 6) {
    std::cerr << "usage: rom-ellipsoid-table a b c TILT_DEG OUT.h5\n";
    return 1;
  }
  try {
    const double tilt = std::stod(argv[4]) * std::numbers::pi / 180;
    rc::write_mode_table(rc::rom::test::ellipsoid_table(std::stod(argv[1]), std::stod(argv[2]), std::stod(argv[3]), tilt),
                         argv[5]);
  } catch (const std::exception& e) {
    std::cerr << "rom-ellipsoid-table: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
