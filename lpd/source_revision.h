// lpd: the source revision a binary was built from, so that every run and sweep can say what
// produced it (cmake/source_revision.cmake writes the definition at build time).
#ifndef LPD_SOURCE_REVISION_H_
#define LPD_SOURCE_REVISION_H_

namespace lpd {

// The short git revision, "REVISION-dirty" when tracked files differed from it at the build,
// or "unknown" when the sources were not a git checkout.
const char* SourceRevision();

}  // namespace lpd

#endif  // LPD_SOURCE_REVISION_H_
