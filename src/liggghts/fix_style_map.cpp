// Modify's fix style map, reached through a pointer to member named in an explicit
// instantiation (the access rules do not apply there).
#include "liggghts/fix_style_map.h"

#include <map>
#include <string>

namespace lubricated {
namespace liggghts {

namespace {

using FixMap = std::map<std::string, FixCreator>;
using FixMapMember = FixMap *LAMMPS_NS::Modify::*;

FixMapMember fix_map_member();
template <FixMapMember member> struct FixMapAccess {
  friend FixMapMember fix_map_member() { return member; }
};
template struct FixMapAccess<&LAMMPS_NS::Modify::fix_map>;

}    // namespace

void add_fix_style(LAMMPS_NS::Modify *modify, const char *style, FixCreator creator)
{
  FixMap *styles = modify->*fix_map_member();
  if (styles->find(style) == styles->end()) (*styles)[style] = creator;
}

}    // namespace liggghts
}    // namespace lubricated
