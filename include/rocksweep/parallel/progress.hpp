#pragma once
/// Progress report of a sweep: a redrawn bar on a terminal, a plain line every few seconds in a
/// log file, nothing when quiet. Knows nothing of MPI: make one on rank 0 only.
#include <chrono>
#include <cstddef>
#include <iostream>
#include <ostream>
#include <string>

namespace rocksweep {

struct ProgressOptions {
    enum class Style {
        automatic,  ///< bar if the stream is std::cerr/std::clog and stderr is a terminal (std::cout: stdout), else plain
        bar,        ///< `[#####.....] 12345/100000 cells  1234 cells/s  ETA 1m12s`, redrawn in place with \r
        plain,      ///< one such line (without the bar) per plain_interval_s
    };
    Style style = Style::automatic;
    double bar_interval_s = 0.1;    ///< least time between two redraws of the bar
    double plain_interval_s = 5.0;  ///< least time between two plain lines
    int bar_width = 30;             ///< characters between the brackets
    /// Cells already done before this run started (a resumed sweep): counted in done/total,
    /// left out of the rate and the ETA.
    std::size_t already_done = 0;
};

class Progress {
public:
    /// `total`: cells of the whole sweep. `quiet`: print nothing at all.
    Progress(std::size_t total, bool quiet, std::ostream& out = std::cerr, ProgressOptions options = {});
    /// Ends an unfinished bar's line so that what follows starts on a fresh line.
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// `done` cells (already_done included) are finished; prints if the interval has passed.
    void update(std::size_t done);
    /// Prints the final line: cells done, total time, mean rate. With no argument, the last
    /// value given to update(). Later calls do nothing.
    void finish();
    void finish(std::size_t done);

    bool uses_bar() const noexcept { return bar_; }

    /// 0.4 -> "0.4s", 42 -> "42s", 72 -> "1m12s", 7384 -> "2h03m", 200000 -> "2d07h".
    static std::string format_duration(double seconds);
    /// Cells per second with three significant figures below 100: "0.512", "12.5", "1234".
    static std::string format_rate(double cells_per_s);

private:
    using Clock = std::chrono::steady_clock;

    std::string status(std::size_t done, double elapsed_s) const;
    void draw(const std::string& text, bool final);

    std::size_t total_;
    bool quiet_;
    std::ostream& out_;
    ProgressOptions options_;
    bool bar_ = false;
    bool finished_ = false;
    bool bar_drawn_ = false;     ///< a bar line is on screen without its newline
    std::size_t last_width_ = 0; ///< length of the bar line on screen, to blank what a shorter one leaves
    std::size_t last_done_ = 0;
    Clock::time_point start_;
    Clock::time_point last_print_;
};

}  // namespace rocksweep
