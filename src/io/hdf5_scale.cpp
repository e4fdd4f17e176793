// Dimension scales (H5DS, in hdf5_hl): the swept axes attached to every result dataset so that
// h5py, xarray and netCDF readers see named axes. Apart because it is the only piece that needs
// the high-level library.
#include <hdf5_hl.h>

#include <string>

#include "hdf5_detail.hpp"
#include "rocksweep/io/hdf5.hpp"

namespace rocksweep::h5 {

using detail::in_quotes;

void make_scale(const Dataset& scale, std::string_view scale_name) {
    const std::string n(scale_name);
    check(H5DSset_scale(scale.id(), n.c_str()), "making " + in_quotes(scale.name()) + " a dimension scale");
}

void attach_scale(const Dataset& data, const Dataset& scale, unsigned dim) {
    check(H5DSattach_scale(data.id(), scale.id(), dim),
          "attaching " + in_quotes(scale.name()) + " to dimension " + std::to_string(dim) + " of " +
              in_quotes(data.name()));
}

bool is_attached(const Dataset& data, const Dataset& scale, unsigned dim) {
    return check(H5DSis_attached(data.id(), scale.id(), dim),
                 "checking the scale of dimension " + std::to_string(dim) + " of " +
                     in_quotes(data.name())) > 0;
}

void set_dimension_label(const Dataset& data, unsigned dim, std::string_view label) {
    const std::string l(label);
    check(H5DSset_label(data.id(), dim, l.c_str()),
          "labelling dimension " + std::to_string(dim) + " of " + in_quotes(data.name()));
}

}  // namespace rocksweep::h5
