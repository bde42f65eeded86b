// Small shared helpers of the yarn stage: a fixed partition of work over threads (so that
// results depend only on the thread count) and a median.
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace skein {

// Calls work(begin, end, part) for `parts` contiguous slices of [0, n), on parts threads.
template <class Work>
void parallel_for(std::size_t n, unsigned parts, const Work& work) {
  parts = std::max(1u, std::min<unsigned>(parts, static_cast<unsigned>(n / 1024 + 1)));
  if (parts == 1) return work(std::size_t{0}, n, 0u);
  std::vector<std::thread> threads;
  for (unsigned p = 1; p < parts; ++p)
    threads.emplace_back([&, p] { work(n * p / parts, n * (p + 1) / parts, p); });
  work(0, n / parts, 0u);
  for (std::thread& t : threads) t.join();
}

inline unsigned default_threads() {
  return std::max(1u, std::thread::hardware_concurrency());
}

inline float median(std::vector<float> values, float fallback) {
  if (values.empty()) return fallback;
  auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle > 0 ? *middle : fallback;
}

}  // namespace skein
