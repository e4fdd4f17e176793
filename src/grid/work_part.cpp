#include "rocksweep/grid/work_part.hpp"

#include <algorithm>
#include <charconv>

#include "rocksweep/core/errors.hpp"

namespace rocksweep {

namespace {

bool parse_count(const std::string& s, std::size_t& out) {
    if (s.empty() || s.size() > 7) return false;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size();
}

}  // namespace

WorkPart parse_work_part(const std::string& text) {
    const std::string allowed = "K/N, part K of N, with 1 <= K <= N <= 1000000 (e.g. 3/10)";
    const auto slash = text.find('/');
    WorkPart p;
    if (slash == std::string::npos || !parse_count(text.substr(0, slash), p.index) ||
        !parse_count(text.substr(slash + 1), p.count) || p.index < 1 || p.count < 1 || p.index > p.count ||
        p.count > 1000000)
        throw InputError("part", text, allowed);
    return p;
}

std::vector<IndexRange> restrict_to_part(const std::vector<IndexRange>& todo, WorkPart part) {
    std::vector<IndexRange> out;
    const std::size_t stride = kPartBlock * part.count;
    const std::size_t offset = kPartBlock * (part.index - 1);
    for (const IndexRange& r : todo) {
        const std::size_t end = r.first + r.count;
        // The first block of this part at or before r.first, then every stride-th one.
        std::size_t block = r.first < offset ? offset : r.first - (r.first - offset) % stride;
        for (; block < end; block += stride) {
            const std::size_t lo = std::max(block, r.first), hi = std::min(block + kPartBlock, end);
            if (lo >= hi) continue;
            if (!out.empty() && out.back().first + out.back().count == lo) out.back().count += hi - lo;
            else out.push_back({lo, hi - lo});
        }
    }
    return out;
}

std::size_t cells_in_part(std::size_t total, WorkPart part) {
    std::size_t n = 0;
    for (const IndexRange& r : restrict_to_part({{0, total}}, part)) n += r.count;
    return n;
}

}  // namespace rocksweep
