#pragma once
/// Boundary refinement of a 2-D grid of outcomes: compute a coarse lattice, then only the
/// squares whose corners disagree (and their neighbours), halving the spacing each pass, down
/// to the full grid. Cells inside squares whose corners all agree take that outcome.
/// Knows nothing of what an outcome means, nor of how cells are computed.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rocksweep {

/// Values of SweepResults::done.
inline constexpr std::uint8_t cell_pending = 0;
inline constexpr std::uint8_t cell_computed = 1;
inline constexpr std::uint8_t cell_inferred = 2;  ///< outcome taken from a uniform square

class Refinement {
public:
    /// A rows x cols grid, first lattice spacing `coarse_stride` (a power of 2, >= 2); `halo`
    /// also refines the squares next to a mixed one, which catches a boundary that enters and
    /// leaves a square between its corners.
    Refinement(std::size_t rows, std::size_t cols, std::size_t coarse_stride, bool halo = true);

    /// Passes: the coarse lattice, then one per halving of the spacing.
    int passes() const { return passes_; }

    /// Flat indices (row * cols + col) to compute in pass k, given what is known so far;
    /// cells already computed are left out. `outcome` and `done` have rows * cols entries.
    std::vector<std::size_t> cells_for_pass(int k, const std::uint8_t* outcome, const std::uint8_t* done) const;

    /// After the last pass: every cell not computed takes the outcome of the smallest uniform
    /// square around it and is marked cell_inferred.
    void fill(std::uint8_t* outcome, std::uint8_t* done) const;

private:
    std::size_t rows_, cols_, stride_;
    bool halo_;
    int passes_;
    /// Lattice of spacing s along an axis of n points: multiples of s and the last point.
    static std::vector<std::size_t> lattice(std::size_t n, std::size_t s);
    /// Squares of the lattice of spacing s whose four corners are computed and disagree.
    std::vector<std::uint8_t> mixed_squares(std::size_t s, const std::uint8_t* outcome, const std::uint8_t* done,
                                            std::vector<std::size_t>& r, std::vector<std::size_t>& c) const;
};

}  // namespace rocksweep
