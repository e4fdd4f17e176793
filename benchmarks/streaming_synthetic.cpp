// A sweep whose cells cost a chosen number of nanoseconds and hold made-up values, driven
// through the real MPI scheduler and the streaming spectra writer (SpectraStream) with the
// checkpoint policy of `rocksweep sweep` (every --checkpoint seconds, and early when rank 0
// holds 64 MiB). It shows what the writer costs rank 0 at grid sizes the physics would take
// hours to fill: peak memory (VmHWM) and the time spent checkpointing.
// benchmarks/streaming_scale.sh runs it; benchmarks/results/streaming.md has the figures.
#include <chrono>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "rocksweep/io/spectra_stream.hpp"
#include "rocksweep/parallel/mpi_session.hpp"
#include "rocksweep/parallel/scheduler.hpp"
#include "rocksweep/physics/integrator.hpp"

using namespace rocksweep;

namespace {

/// Peak resident memory of this process [MiB], from /proc/self/status.
double vm_hwm_mib() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
    return -1.0;
}

void spin_for(double ns) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::nanoseconds(static_cast<long long>(ns));
    while (std::chrono::steady_clock::now() < until) {
    }
}

}  // namespace

int main(int argc, char** argv) {
    MpiSession mpi(argc, argv);
    CLI::App app("streaming writer benchmark with a synthetic cell cost");
    std::size_t rows = 1000, cols = 1000, chunk = 4096;
    double cell_ns = 0.0, checkpoint_s = 5.0;
    std::string out = "synthetic.h5";
    app.add_option("--rows", rows, "amplitude points")->capture_default_str();
    app.add_option("--cols", cols, "omega points")->capture_default_str();
    app.add_option("--cell-ns", cell_ns, "cost of one cell [ns]")->capture_default_str();
    app.add_option("--chunk", chunk, "largest chunk")->capture_default_str();
    app.add_option("--checkpoint", checkpoint_s, "checkpoint interval [s]")->capture_default_str();
    app.add_option("-o", out, "output file (replaced)")->capture_default_str();
    CLI11_PARSE(app, argc, argv);

    SweepSpec spec;
    spec.amplitude_ratio = {1.0, 5.0, rows};
    spec.omega_ratio = {0.5, 10.0, cols};
    spec.scenarios.push_back({"free", free_anchorage(), 0.0, 1.0});
    const IntegratorSettings settings;
    Provenance prov;
    prov.version = "streaming_synthetic";
    prov.ranks = mpi.size();
    constexpr std::size_t max_pending_bytes = std::size_t{64} << 20;  // as in sweep_command.cpp

    std::optional<SpectraStream> stream;
    if (mpi.is_root()) stream.emplace(out, spec, settings, prov, false);
    const double t0 = MpiSession::wall_time();
    double last = t0;
    auto checkpoint = [&] {
        stream->checkpoint();
        last = MpiSession::wall_time();
    };
    ScheduleOptions so;
    so.record_bytes = sizeof(CellResult);
    so.max_chunk = chunk;
    so.min_chunk = std::min<std::size_t>(8, chunk);
    so.tick_interval_s = std::min(0.5, checkpoint_s / 2);
    so.on_tick = [&] {
        if (MpiSession::wall_time() - last >= checkpoint_s) checkpoint();
    };
    const ComputeFn compute = [&](std::size_t first, std::size_t count, std::byte* bytes) {
        spin_for(cell_ns * static_cast<double>(count));
        for (std::size_t i = 0; i < count; ++i) {
            CellResult r;
            const std::size_t k = first + i;
            r.max_rotation = static_cast<double>(k % 1000) * 1e-3;
            r.t_overturn_s = static_cast<double>(k % 7);
            r.impacts = static_cast<std::int32_t>(k % 5);
            r.outcome = static_cast<Outcome>(k % 3);
            std::memcpy(bytes + i * sizeof r, &r, sizeof r);
        }
    };
    std::vector<CellResult> cells;
    const SinkFn sink = [&](std::size_t first, std::size_t count, const std::byte* records) {
        cells.resize(count);
        std::memcpy(cells.data(), records, count * sizeof(CellResult));
        stream->add(first, count, cells.data());
        if (stream->pending_bytes() >= max_pending_bytes) checkpoint();
    };
    const auto scheduler = make_mpi_scheduler(mpi.comm());
    const ScheduleStats stats = scheduler->run({{0, spec.cell_count()}}, so, compute, sink);
    if (!mpi.is_root()) return 0;
    const double wall = MpiSession::wall_time() - t0;
    stream->finish(wall);
    const CheckpointStats& c = stream->stats();
    std::cout << "cells " << stats.cells_done << " ranks " << mpi.size() << " wall_s " << wall << " cells_per_s "
              << static_cast<double>(stats.cells_done) / wall << " checkpoints " << c.checkpoints << " checkpoint_s "
              << c.seconds << " overhead_pct " << 100.0 * c.seconds / wall << " rank0_vmhwm_mib " << vm_hwm_mib() << "\n";
    return 0;
}
