#pragma once
// What each column of the accuracy table means, printed under it.
#include <ostream>

namespace sweeptrace::accuracy {

void write_legend(std::ostream& out);

}  // namespace sweeptrace::accuracy
