#pragma once
// The build's version, `git describe --always --dirty` of the checkout it was built from
// ("unknown" outside git): farm parts record it, so parts of two different builds, which may
// draw different samples, are never merged (two builds of one commit with different uncommitted
// edits both say "<commit>-dirty" and are not told apart). Defined in a file generated at build
// time (tools/cmake/program_version.cmake).
namespace sweeptrace {

const char* program_version();

}  // namespace sweeptrace
