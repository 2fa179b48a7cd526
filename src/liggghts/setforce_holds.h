// Whether a LIGGGHTS fix setforce holds its atoms: every component the constant 0 and no region
// (the LAMMPS plugin's rule, src/contact_mass/). LIGGGHTS keeps those arguments private; they are
// read through the one access C++ grants to private members, a pointer to member named in an
// explicit instantiation.
#pragma once

#include "fix_setforce.h"

namespace lubricated {
namespace liggghts {
namespace setforce_detail {

using IntMember = int LAMMPS_NS::FixSetForce::*;
using DoubleMember = double LAMMPS_NS::FixSetForce::*;
using TextMember = char *LAMMPS_NS::FixSetForce::*;

struct Members {
  IntMember style[3];
  DoubleMember value[3];
  TextMember region;
};

Members members();
template <IntMember X, IntMember Y, IntMember Z, DoubleMember VX, DoubleMember VY, DoubleMember VZ, TextMember REGION>
struct Access {
  friend Members members() { return Members{{X, Y, Z}, {VX, VY, VZ}, REGION}; }
};
template struct Access<&LAMMPS_NS::FixSetForce::xstyle, &LAMMPS_NS::FixSetForce::ystyle,
                       &LAMMPS_NS::FixSetForce::zstyle, &LAMMPS_NS::FixSetForce::xvalue,
                       &LAMMPS_NS::FixSetForce::yvalue, &LAMMPS_NS::FixSetForce::zvalue,
                       &LAMMPS_NS::FixSetForce::idregion>;

// fix_setforce.cpp: enum {NONE, CONSTANT, EQUAL, ATOM}.
constexpr int constant_style = 1;

}    // namespace setforce_detail

inline bool setforce_holds(LAMMPS_NS::Fix *fix)
{
  auto *setforce = static_cast<LAMMPS_NS::FixSetForce *>(fix);
  const setforce_detail::Members m = setforce_detail::members();
  for (int d = 0; d < 3; d++)
    if (setforce->*m.style[d] != setforce_detail::constant_style || setforce->*m.value[d] != 0.0) return false;
  return setforce->*m.region == nullptr;
}

}    // namespace liggghts
}    // namespace lubricated
