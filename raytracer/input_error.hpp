#pragma once
// Bad input from the user (scene, mesh, image, command line). The CLI prints what() on one line
// and exits with code 2; nothing is written. Messages name the file and where in it
// (JSON path such as `objects[3].radius`, or line and column).
#include <stdexcept>
#include <string>

namespace sweeptrace {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace sweeptrace
