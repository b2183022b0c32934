#include <feran/core/types.hpp>

namespace feran {

const char* dof_name(Dof d) {
  switch (d) {
    case Dof::u:
      return "u";
    case Dof::v:
      return "v";
    case Dof::w:
      return "w";
    case Dof::rx:
      return "rx";
    case Dof::ry:
      return "ry";
    case Dof::rz:
      return "rz";
  }
  return "?";
}

}  // namespace feran
