#pragma once
/// The 2-D planes that boundary refinement works on within one scenario's block of cells: the
/// pair of axes it refines over (by default the two a spectrum is drawn on), every combination
/// of the other axes one plane. Knows axis sizes and C order, nothing of what they mean.
#include <cstddef>
#include <vector>

namespace rocksweep {

class RefinePlanes {
public:
    /// `sizes`: every axis of the grid in C order (the first varies slowest); refinement runs
    /// over axes `row` and `col` (row < col). Throws std::invalid_argument otherwise.
    RefinePlanes(std::vector<std::size_t> sizes, std::size_t row, std::size_t col);

    std::size_t count() const { return count_; }
    std::size_t rows() const { return sizes_[row_]; }
    std::size_t cols() const { return sizes_[col_]; }
    std::size_t row_axis() const { return row_; }  ///< position of the row axis in C order
    std::size_t col_axis() const { return col_; }
    /// Index within the scenario of cell (r, c) of plane `plane`.
    std::size_t cell(std::size_t plane, std::size_t r, std::size_t c) const {
        return base(plane) + r * stride_[row_] + c * stride_[col_];
    }
    /// The cells of `plane`, from its first to its last: the span a reader fetches to gather it.
    std::size_t first(std::size_t plane) const { return base(plane); }
    std::size_t span() const { return (rows() - 1) * stride_[row_] + (cols() - 1) * stride_[col_] + 1; }
    /// Whether every plane is one contiguous run of cells (the pair is the last two axes).
    bool contiguous() const { return span() == rows() * cols(); }

private:
    std::size_t base(std::size_t plane) const;
    std::vector<std::size_t> sizes_, stride_;
    std::size_t row_, col_, count_;
};

}  // namespace rocksweep
