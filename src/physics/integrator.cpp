#include "rocksweep/physics/integrator.hpp"

#include <stdexcept>
#include <type_traits>

#include "lane.hpp"
#include "springs.hpp"

namespace rocksweep {

std::string to_string(Method m) { return m == Method::events ? "events" : "paper"; }

std::string to_string(Outcome o) {
    switch (o) {
        case Outcome::safe: return "safe";
        case Outcome::overturned_impact: return "overturned_with_impact";
        case Outcome::overturned_no_impact: return "overturned_without_impact";
        case Outcome::not_converged: return "not_converged";
    }
    return "?";
}

namespace {

/// The anchorage law each kind of anchorage runs (anchorage_law.hpp): f(std::type_identity<Law>).
/// A new law is registered here, with its AnchorageKind (anchorage.hpp).
template <class F>
decltype(auto) with_law(AnchorageKind kind, F&& f) {
    switch (kind) {
        case AnchorageKind::free:
        case AnchorageKind::constant:
        case AnchorageKind::adaptive: return f(std::type_identity<kernel::Springs>{});
    }
    throw std::logic_error("integrate_cells: an anchorage kind without a law");
}

bool same_law(AnchorageKind a, AnchorageKind b) {
    return with_law(a, [&](auto la) {
        return with_law(b, [&](auto lb) { return std::is_same_v<decltype(la), decltype(lb)>; });
    });
}

template <int W>
void run_cells(std::span<const CellModel> cells, std::span<CellResult> results, const IntegratorSettings& settings,
               const StepObserver* obs, BatchStats* stats = nullptr) {
    // Each stretch of cells that share a law is one batch run: with one law, the whole span.
    for (std::size_t i = 0; i < cells.size();) {
        std::size_t j = i + 1;
        while (j < cells.size() && same_law(cells[i].anchorage, cells[j].anchorage)) ++j;
        with_law(cells[i].anchorage, [&]<class Law>(std::type_identity<Law>) {
            kernel::run_lanes<W, Law>(cells.subspan(i, j - i), results.subspan(i, j - i), settings, obs, stats);
        });
        i = j;
    }
}

}  // namespace

void integrate_cells(std::span<const CellModel> cells, std::span<CellResult> results,
                     const IntegratorSettings& settings, int lanes, BatchStats* stats) {
    if (results.size() != cells.size()) throw std::invalid_argument("integrate_cells: size mismatch");
    if (stats) stats->lanes = lanes;
    switch (lanes) {
        case 1: return run_cells<1>(cells, results, settings, nullptr, stats);
        case 4: return run_cells<4>(cells, results, settings, nullptr, stats);
        case 8: return run_cells<8>(cells, results, settings, nullptr, stats);
        case 16: return run_cells<16>(cells, results, settings, nullptr, stats);
        default: throw std::invalid_argument("integrate_cells: lanes must be 1, 4, 8 or 16");
    }
}

CellResult integrate_cell(const CellModel& cell, const IntegratorSettings& settings, const StepObserver& observer) {
    CellResult r;
    run_cells<1>(std::span<const CellModel>(&cell, 1), std::span<CellResult>(&r, 1), settings,
                 observer ? &observer : nullptr);
    return r;
}

}  // namespace rocksweep
