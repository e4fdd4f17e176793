#include "rocksweep/grid/refine.hpp"

#include <algorithm>
#include <stdexcept>

namespace rocksweep {

Refinement::Refinement(std::size_t rows, std::size_t cols, std::size_t coarse_stride, bool halo)
    : rows_(rows), cols_(cols), stride_(coarse_stride), halo_(halo), passes_(1) {
    if (coarse_stride < 2 || (coarse_stride & (coarse_stride - 1)) != 0)
        throw std::invalid_argument("Refinement: coarse stride must be a power of 2, at least 2");
    for (std::size_t s = coarse_stride; s > 1; s /= 2) ++passes_;
}

std::vector<std::size_t> Refinement::lattice(std::size_t n, std::size_t s) {
    std::vector<std::size_t> v;
    for (std::size_t i = 0; i < n; i += s) v.push_back(i);
    if (v.back() != n - 1) v.push_back(n - 1);
    return v;
}

std::vector<std::uint8_t> Refinement::mixed_squares(std::size_t s, const std::uint8_t* outcome,
                                                    const std::uint8_t* done, std::vector<std::size_t>& r,
                                                    std::vector<std::size_t>& c) const {
    r = lattice(rows_, s);
    c = lattice(cols_, s);
    const std::size_t nr = r.size() > 1 ? r.size() - 1 : 1, nc = c.size() > 1 ? c.size() - 1 : 1;
    std::vector<std::uint8_t> mixed(nr * nc, 0);
    for (std::size_t i = 0; i < nr; ++i) {
        for (std::size_t j = 0; j < nc; ++j) {
            const std::size_t r1 = r[std::min(i + 1, r.size() - 1)], c1 = c[std::min(j + 1, c.size() - 1)];
            const std::size_t corners[4] = {r[i] * cols_ + c[j], r[i] * cols_ + c1, r1 * cols_ + c[j], r1 * cols_ + c1};
            bool all_known = true, differ = false;
            for (std::size_t k : corners) {
                all_known = all_known && done[k] == cell_computed;
                differ = differ || outcome[k] != outcome[corners[0]];
            }
            mixed[i * nc + j] = all_known && differ;
        }
    }
    if (!halo_) return mixed;
    std::vector<std::uint8_t> grown = mixed;
    for (std::size_t i = 0; i < nr; ++i)
        for (std::size_t j = 0; j < nc; ++j)
            if (mixed[i * nc + j])
                for (std::size_t a = i ? i - 1 : 0; a <= std::min(i + 1, nr - 1); ++a)
                    for (std::size_t b = j ? j - 1 : 0; b <= std::min(j + 1, nc - 1); ++b) grown[a * nc + b] = 1;
    return grown;
}

namespace {
/// Points lo, lo + s, ... below hi, and hi.
std::vector<std::size_t> between(std::size_t lo, std::size_t hi, std::size_t s) {
    std::vector<std::size_t> v;
    for (std::size_t x = lo; x < hi; x += s) v.push_back(x);
    v.push_back(hi);
    return v;
}
}  // namespace

std::vector<std::size_t> Refinement::cells_for_pass(int k, const std::uint8_t* outcome, const std::uint8_t* done) const {
    std::vector<std::uint8_t> want(rows_ * cols_, 0);
    const std::size_t s = std::max<std::size_t>(1, stride_ >> k);
    if (k == 0) {
        for (std::size_t i : lattice(rows_, s))
            for (std::size_t j : lattice(cols_, s)) want[i * cols_ + j] = 1;
    } else {
        // Squares of the previous lattice whose corners disagree: all their points at spacing s.
        std::vector<std::size_t> r, c;
        const std::vector<std::uint8_t> mixed = mixed_squares(2 * s, outcome, done, r, c);
        const std::size_t nc = c.size() > 1 ? c.size() - 1 : 1;
        for (std::size_t q = 0; q < mixed.size(); ++q) {
            if (!mixed[q]) continue;
            const std::size_t i = q / nc, j = q % nc;
            const std::size_t r0 = r[i], r1 = r[std::min(i + 1, r.size() - 1)];
            const std::size_t c0 = c[j], c1 = c[std::min(j + 1, c.size() - 1)];
            for (std::size_t a : between(r0, r1, s))
                for (std::size_t b : between(c0, c1, s)) want[a * cols_ + b] = 1;
        }
    }
    std::vector<std::size_t> cells;
    for (std::size_t i = 0; i < want.size(); ++i)
        if (want[i] && done[i] != cell_computed) cells.push_back(i);
    return cells;
}

void Refinement::fill(std::uint8_t* outcome, std::uint8_t* done) const {
    // Fine to coarse: a pending cell takes the outcome of the smallest uniform square of
    // computed corners around it (a halo may have computed cells inside a coarse square).
    for (std::size_t s = 2; s <= stride_; s *= 2) {
        const std::vector<std::size_t> r = lattice(rows_, s), c = lattice(cols_, s);
        for (std::size_t i = 0; i < std::max<std::size_t>(1, r.size() - 1); ++i) {
            for (std::size_t j = 0; j < std::max<std::size_t>(1, c.size() - 1); ++j) {
                const std::size_t r0 = r[i], r1 = r[std::min(i + 1, r.size() - 1)];
                const std::size_t c0 = c[j], c1 = c[std::min(j + 1, c.size() - 1)];
                const std::size_t corners[4] = {r0 * cols_ + c0, r0 * cols_ + c1, r1 * cols_ + c0, r1 * cols_ + c1};
                bool uniform = true;
                for (std::size_t k : corners)
                    uniform = uniform && done[k] == cell_computed && outcome[k] == outcome[corners[0]];
                if (!uniform) continue;
                for (std::size_t a = r0; a <= r1; ++a)
                    for (std::size_t b = c0; b <= c1; ++b)
                        if (done[a * cols_ + b] == cell_pending) {
                            outcome[a * cols_ + b] = outcome[corners[0]];
                            done[a * cols_ + b] = cell_inferred;
                        }
            }
        }
    }
}

}  // namespace rocksweep
