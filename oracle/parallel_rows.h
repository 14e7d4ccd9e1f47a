// Rows of an image handed out one at a time to up to `max_threads` threads (the calling one included).
// Every row must be independent of the others, so the result does not depend on timing. `row(y)`
// returns a count (rays cast); the sum over all rows is returned.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <vector>

namespace shadowlab {

// Threads the ray-cast truths use (oracle.cpp's hard truth, soft_truth.cpp's soft one): the lab's
// machines have two cores, and no output depends on it.
inline constexpr unsigned kTruthThreads = 2;

template <typename RowFn>
std::uint64_t for_each_row_parallel(std::size_t height, unsigned max_threads, const RowFn& row) {
  std::atomic<std::size_t> next_row{0};
  std::atomic<std::uint64_t> total{0};
  auto worker = [&] {
    std::uint64_t sum = 0;
    for (std::size_t y = next_row++; y < height; y = next_row++) sum += row(y);
    total += sum;
  };
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t thread_count = std::min<std::size_t>({max_threads, hardware, std::max<std::size_t>(height, 1)});
  std::vector<std::thread> threads;
  for (std::size_t t = 1; t < thread_count; ++t) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  return total.load();
}

}  // namespace shadowlab
