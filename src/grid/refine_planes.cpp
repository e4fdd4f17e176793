#include "rocksweep/grid/refine_planes.hpp"

#include <stdexcept>

namespace rocksweep {

RefinePlanes::RefinePlanes(std::vector<std::size_t> sizes, std::size_t row, std::size_t col)
    : sizes_(std::move(sizes)), stride_(sizes_.size(), 1), row_(row), col_(col), count_(1) {
    if (!(row < col && col < sizes_.size())) throw std::invalid_argument("RefinePlanes: needs row < col < axes");
    for (std::size_t k = sizes_.size() - 1; k-- > 0;) stride_[k] = stride_[k + 1] * sizes_[k + 1];
    for (std::size_t k = 0; k < sizes_.size(); ++k)
        if (k != row_ && k != col_) count_ *= sizes_[k];
}

std::size_t RefinePlanes::base(std::size_t plane) const {
    // The plane's coordinates on the other axes, fastest last, as in the grid.
    std::size_t index = 0;
    for (std::size_t k = sizes_.size(); k-- > 0;) {
        if (k == row_ || k == col_) continue;
        index += (plane % sizes_[k]) * stride_[k];
        plane /= sizes_[k];
    }
    return index;
}

}  // namespace rocksweep
