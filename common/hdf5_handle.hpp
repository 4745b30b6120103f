// RAII for HDF5 identifiers, shared by the mode table and its fields (internal to rc_common).
#pragma once

#include <hdf5.h>

namespace rc {

// Owns one HDF5 identifier; the close function depends on the kind of object (H5Fclose, H5Gclose, ...).
class Hid {
 public:
  Hid(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Hid(const Hid&) = delete;
  Hid& operator=(const Hid&) = delete;
  ~Hid() { if (id_ >= 0) close_(id_); }
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

}  // namespace rc
