#include "rocksweep/parallel/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rocksweep {

namespace {

bool stream_is_terminal(const std::ostream& out) {
    if (&out == &std::cerr || &out == &std::clog) return ::isatty(STDERR_FILENO) == 1;
    if (&out == &std::cout) return ::isatty(STDOUT_FILENO) == 1;
    return false;
}

}  // namespace

Progress::Progress(std::size_t total, bool quiet, std::ostream& out, ProgressOptions options)
    : total_(total), quiet_(quiet), out_(out), options_(options), last_done_(options.already_done),
      start_(Clock::now()), last_print_(start_) {
    switch (options_.style) {
        case ProgressOptions::Style::bar: bar_ = true; break;
        case ProgressOptions::Style::plain: bar_ = false; break;
        case ProgressOptions::Style::automatic: bar_ = stream_is_terminal(out_); break;
    }
    options_.bar_width = std::max(options_.bar_width, 1);
}

Progress::~Progress() {
    if (bar_drawn_ && !finished_) {
        try {
            out_ << '\n' << std::flush;
        } catch (...) {
        }
    }
}

void Progress::update(std::size_t done) {
    last_done_ = done;
    if (quiet_ || finished_) return;
    const auto now = Clock::now();
    const double since_print = std::chrono::duration<double>(now - last_print_).count();
    if (bar_) {
        if (bar_drawn_ && since_print < options_.bar_interval_s) return;
    } else if (since_print < options_.plain_interval_s) {
        return;
    }
    last_print_ = now;
    draw(status(done, std::chrono::duration<double>(now - start_).count()), false);
}

void Progress::finish() { finish(last_done_); }

void Progress::finish(std::size_t done) {
    last_done_ = done;
    if (finished_) return;
    finished_ = true;
    if (quiet_) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const std::size_t new_cells = done > options_.already_done ? done - options_.already_done : 0;
    std::string text = status(done, -1.0);
    text += "  in " + format_duration(elapsed) + ", mean ";
    text += elapsed > 0.0 ? format_rate(static_cast<double>(new_cells) / elapsed) : std::string("--");
    text += " cells/s";
    draw(text, true);
}

std::string Progress::status(std::size_t done, double elapsed_s) const {
    std::string text;
    if (bar_) {
        const double fraction = total_ == 0 ? 1.0 : std::min(1.0, static_cast<double>(done) / static_cast<double>(total_));
        const auto filled = static_cast<std::size_t>(fraction * options_.bar_width);
        text += '[';
        text.append(filled, '#');
        text.append(static_cast<std::size_t>(options_.bar_width) - filled, '.');
        text += "] ";
    }
    text += std::to_string(done) + "/" + std::to_string(total_) + " cells";
    if (!bar_ && total_ > 0) {
        char percent[32];
        std::snprintf(percent, sizeof percent, " (%.1f%%)", 100.0 * static_cast<double>(done) / static_cast<double>(total_));
        text += percent;
    }
    if (elapsed_s < 0.0) return text;  // the final line reports time and rate itself

    const std::size_t new_cells = done > options_.already_done ? done - options_.already_done : 0;
    const double rate = elapsed_s > 0.0 ? static_cast<double>(new_cells) / elapsed_s : 0.0;
    if (rate > 0.0) {
        text += "  " + format_rate(rate) + " cells/s";
        const std::size_t left = total_ > done ? total_ - done : 0;
        text += "  ETA " + format_duration(static_cast<double>(left) / rate);
    } else {
        text += "  -- cells/s  ETA --";
    }
    return text;
}

void Progress::draw(const std::string& text, bool final) {
    if (bar_) {
        out_ << '\r' << text;
        if (text.size() < last_width_) out_ << std::string(last_width_ - text.size(), ' ');
        last_width_ = text.size();
        bar_drawn_ = !final;
        if (final) out_ << '\n';
    } else {
        out_ << text << '\n';
    }
    out_.flush();
}

std::string Progress::format_duration(double seconds) {
    if (!(seconds >= 0.0) || !std::isfinite(seconds)) return "--";
    char text[48];
    if (seconds < 9.95) {
        std::snprintf(text, sizeof text, "%.1fs", seconds);
        return text;
    }
    const long long s = std::llround(seconds);
    if (s < 60)
        std::snprintf(text, sizeof text, "%llds", s);
    else if (s < 3600)
        std::snprintf(text, sizeof text, "%lldm%02llds", s / 60, s % 60);
    else if (s < 86400)
        std::snprintf(text, sizeof text, "%lldh%02lldm", s / 3600, (s % 3600) / 60);
    else
        std::snprintf(text, sizeof text, "%lldd%02lldh", s / 86400, (s % 86400) / 3600);
    return text;
}

std::string Progress::format_rate(double cells_per_s) {
    if (!(cells_per_s >= 0.0) || !std::isfinite(cells_per_s)) return "--";
    char text[48];
    if (cells_per_s >= 99.95)
        std::snprintf(text, sizeof text, "%.0f", cells_per_s);
    else if (cells_per_s >= 9.995)
        std::snprintf(text, sizeof text, "%.1f", cells_per_s);
    else
        std::snprintf(text, sizeof text, "%.3g", cells_per_s);
    return text;
}

}  // namespace rocksweep
