// Adds a fix style to a LIGGGHTS instance at run time. LIGGGHTS registers its fix styles at
// compile time, in Modify's private style map; the model's own fixes are added to that map
// through the one access C++ grants to private members (fix_style_map.cpp).
#pragma once

#include "fix.h"
#include "modify.h"

namespace lubricated {
namespace liggghts {

using FixCreator = LAMMPS_NS::Fix *(*)(LAMMPS_NS::LAMMPS *, int, char **);

// Registers style -> creator unless the style exists.
void add_fix_style(LAMMPS_NS::Modify *modify, const char *style, FixCreator creator);

}    // namespace liggghts
}    // namespace lubricated
