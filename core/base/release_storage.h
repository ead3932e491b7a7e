// Letting a vector's memory go. `v = {}` does not: it assigns an empty initializer list, which
// keeps the capacity (a drawn stroke's emptied vertices held 24 bytes a point until the stroke was
// freed). `v.clear()` keeps it too.
#pragma once

namespace tsk {

template <typename Vector>
void release_storage(Vector& v) {
  Vector().swap(v);
}

}  // namespace tsk
