// libliggghts-dev's fix_insert_stream_predefined.h (included by pair_gran_base.h) is a stub
// that does not compile on its own: it derives from FixInsertStream without declaring it and
// lacks has_inserted(). That fix is not part of LIGGGHTS-PUBLIC (the pair loop finds none), so
// the stub gets a base that declares has_inserted() and the real FixInsertStream is never seen.
#pragma once
#include "fix.h"

namespace LAMMPS_NS {
class LubricatedInsertStreamStub : public Fix {
 public:
  bool has_inserted() const { return false; }
};
}    // namespace LAMMPS_NS

// Include pair_gran_base.h right after this header, then #undef FixInsertStream.
#define FixInsertStream LubricatedInsertStreamStub
