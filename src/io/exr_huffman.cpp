#include "io/exr_huffman.h"

#include <algorithm>

#include "io/little_endian.h"

namespace sdfreel {

namespace {

constexpr int MAX_CODE = 58;        // OpenEXR's longest code length
constexpr int SHORT_ZERO_RUN = 59;  // 59-62: 2-5 lengths of 0
constexpr int LONG_ZERO_RUN = 63;   // 63 and 8 bits: 6-261 lengths of 0
constexpr int SHORTEST_LONG_RUN = 2 + LONG_ZERO_RUN - SHORT_ZERO_RUN;
constexpr int LONGEST_LONG_RUN = 255 + SHORTEST_LONG_RUN;

// Bits most significant first into a buffer sized beforehand, as OpenEXR's outputBits writes
// them; a whole 32-bit word at a time. put() takes at most 32 bits, put_long() any count.
class MsbBits {
 public:
  explicit MsbBits(char* out) : start_(out), out_(out) {}
  void put(int count, uint64_t bits) {
    acc_ = (acc_ << count) | bits;
    pending_ += count;
    if (pending_ >= 32) {
      pending_ -= 32;
      const uint32_t w = uint32_t(acc_ >> pending_);
      out_[0] = char(w >> 24);
      out_[1] = char(w >> 16);
      out_[2] = char(w >> 8);
      out_[3] = char(w);
      out_ += 4;
    }
  }
  void put_long(int count, uint64_t bits) {
    if (count > 32) {
      put(count - 32, bits >> 32);
      count = 32;
      bits &= 0xffffffffu;
    }
    put(count, bits);
  }
  // Whole bytes out, the last one padded with zeros; returns the bits written.
  size_t finish() {
    const size_t bits = size_t(out_ - start_) * 8 + size_t(pending_);
    for (; pending_ >= 8; out_++) *out_ = char(acc_ >> (pending_ -= 8));
    if (pending_ > 0) *out_++ = char(acc_ << (8 - pending_));
    pending_ = 0;
    return bits;
  }
  size_t bytes() const { return size_t(out_ - start_); }

 private:
  char* start_;
  char* out_;
  uint64_t acc_ = 0;
  int pending_ = 0;
};

// Runs of one value as hufEncode cuts them, at most 256 values: value | (length - 1) << 16, into
// `runs` (room for n); each whole run's length added to its value's count (neighbouring runs
// hold different values, so no count waits on its own last update). Where a value differs from
// the one before is found sixteen values at a time (the compiler's vector compare). Returns the
// runs written.
size_t find_runs(const uint16_t* in, size_t n, uint32_t* runs, uint32_t* counts) {
  size_t start = 0, written = 0;
  const auto end_run = [&](size_t end) {
    const uint16_t v = in[start];
    size_t length = end - start;
    counts[v] += uint32_t(length);
    for (; length > 256; length -= 256) runs[written++] = v | 255u << 16;
    runs[written++] = v | uint32_t(length - 1) << 16;
    start = end;
  };
  size_t i = 1;
  for (; i + 16 <= n; i += 16) {
    uint32_t differ = 0;
    for (int k = 0; k < 16; ++k)
      differ |= uint32_t(in[i + size_t(k)] != in[i + size_t(k) - 1]) << k;
    for (; differ; differ &= differ - 1) end_run(i + size_t(__builtin_ctz(differ)));
  }
  for (; i < n; ++i)
    if (in[i] != in[i - 1]) end_run(i);
  end_run(n);
  return written;
}

// The symbols present (values in increasing order, then the run pseudo-symbol one above the
// highest): a chunk holds a few thousand of the 65537 possible, so every step below walks these.
struct Codes {
  std::vector<int> symbol;
  std::vector<uint64_t> freq;
  std::vector<uint8_t> length;  // by index into `symbol`
  std::vector<uint64_t> code;
};

// A binary min-heap of keys (frequency << 17 | node): the order is total, so which node comes
// off first does not depend on how the heap is laid out.
class MinHeap {
 public:
  explicit MinHeap(std::vector<uint64_t> keys) : keys_(std::move(keys)) {
    for (size_t i = keys_.size() / 2; i-- > 0;) sift_down(i);
  }
  size_t size() const { return keys_.size(); }
  uint64_t top() const { return keys_[0]; }
  void pop() {
    keys_[0] = keys_.back();
    keys_.pop_back();
    if (!keys_.empty()) sift_down(0);
  }
  void replace_top(uint64_t key) {
    keys_[0] = key;
    sift_down(0);
  }

 private:
  void sift_down(size_t i) {
    const uint64_t key = keys_[i];
    const size_t n = keys_.size();
    for (size_t child; (child = 2 * i + 1) < n; i = child) {
      if (child + 1 < n && keys_[child + 1] < keys_[child]) ++child;
      if (key <= keys_[child]) break;
      keys_[i] = keys_[child];
    }
    keys_[i] = key;
  }
  std::vector<uint64_t> keys_;
};

// hufBuildEncTable's lengths: the two least frequent nodes merged until one is left, ties taken
// in symbol order (its heap compares frequency, then address); a merge lengthens every code below.
void build_lengths(Codes& c) {
  const size_t n = c.symbol.size();
  std::vector<uint64_t> freq = c.freq;
  std::vector<int> link(n);
  std::vector<uint64_t> keys(n);
  for (size_t i = 0; i < n; ++i) {
    link[i] = int(i);
    keys[i] = freq[i] << 17 | i;
  }
  MinHeap heap(std::move(keys));
  c.length.assign(n, 0);
  while (heap.size() > 1) {
    const int mm = int(heap.top() & 0x1ffff);
    heap.pop();
    const int m = int(heap.top() & 0x1ffff);
    freq[size_t(m)] += freq[size_t(mm)];
    heap.replace_top(freq[size_t(m)] << 17 | uint64_t(m));
    for (int j = m;; j = link[size_t(j)]) {
      ++c.length[size_t(j)];
      if (link[size_t(j)] == j) {
        link[size_t(j)] = mm;
        break;
      }
    }
    for (int j = mm;; j = link[size_t(j)]) {
      ++c.length[size_t(j)];
      if (link[size_t(j)] == j) break;
    }
  }
}

// hufCanonicalCodeTable: longer codes numerically lower; within a length, in symbol order.
void canonical_codes(Codes& c) {
  uint64_t first[MAX_CODE + 1] = {};
  for (uint8_t l : c.length) ++first[l];
  uint64_t next = 0;
  for (int l = MAX_CODE; l > 0; --l) {
    const uint64_t below = (next + first[l]) >> 1;
    first[l] = next;
    next = below;
  }
  c.code.resize(c.length.size());
  for (size_t i = 0; i < c.length.size(); ++i) c.code[i] = first[c.length[i]]++;
}

// hufPackEncTable: six bits a length, a run of zero lengths (the values absent between two
// present) in pieces of at most LONGEST_LONG_RUN.
void pack_lengths(const Codes& c, MsbBits& bits) {
  for (size_t i = 0; i < c.symbol.size(); ++i) {
    if (i > 0)
      for (int zeros = c.symbol[i] - c.symbol[i - 1] - 1; zeros > 0;) {
        const int run = zeros < LONGEST_LONG_RUN ? zeros : LONGEST_LONG_RUN;
        if (run >= SHORTEST_LONG_RUN) {
          bits.put(6, LONG_ZERO_RUN);
          bits.put(8, uint64_t(run - SHORTEST_LONG_RUN));
        } else if (run >= 2) {
          bits.put(6, uint64_t(SHORT_ZERO_RUN + run - 2));
        } else {
          bits.put(6, 0);
        }
        zeros -= run;
      }
    bits.put(6, c.length[i]);
  }
}

// hufEncode over the runs: a value repeated `run` more times is the value and the run symbol
// with an 8-bit count where that is shorter than the repeats. `table[value]`: code << 6 | length.
// LONG: some code is over 32 bits (only in theory at a chunk's size).
template <bool LONG>
void encode(const uint64_t* table, uint64_t rlc, const uint32_t* runs, size_t count,
            MsbBits& bits) {
  const auto put = [&](int n, uint64_t b) { LONG ? bits.put_long(n, b) : bits.put(n, b); };
  const int rlc_len = int(rlc & 63);
  for (size_t r = 0; r < count; ++r) {
    const uint64_t entry = table[runs[r] & 0xffff];
    const int run = int(runs[r] >> 16), l = int(entry & 63);
    const uint64_t code = entry >> 6;
    if (l + rlc_len + 8 < l * run) {
      put(l, code);
      put(rlc_len, rlc >> 6);
      put(8, uint64_t(run));
    } else {
      for (int k = 0; k <= run; ++k) put(l, code);
    }
  }
}

}  // namespace

size_t exr_huffman_compress(const uint16_t* raw, size_t n, std::vector<char>& out) {
  if (n == 0) return 0;
  // Tables of every value, kept per thread and cleared where used: a chunk touches few entries.
  thread_local std::vector<uint32_t> counts(size_t(1) << 16);
  thread_local std::vector<uint64_t> table(size_t(1) << 16);
  thread_local std::vector<uint32_t> runs;
  if (runs.size() < n) runs.resize(n);
  const size_t run_count = find_runs(raw, n, runs.data(), counts.data());
  Codes c;
  for (int block = 0; block < (1 << 16); block += 16) {
    uint32_t any = 0;  // sixteen counts at a time: most are zero
    for (int k = 0; k < 16; ++k) any |= counts[size_t(block + k)];
    if (any)
      for (int v = block; v < block + 16; ++v)
        if (counts[size_t(v)]) {
          c.symbol.push_back(v);
          c.freq.push_back(counts[size_t(v)]);
          counts[size_t(v)] = 0;
        }
  }
  c.symbol.push_back(c.symbol.back() + 1);
  c.freq.push_back(1);
  build_lengths(c);
  canonical_codes(c);
  const size_t values = c.symbol.size() - 1;
  for (size_t i = 0; i < values; ++i) table[size_t(c.symbol[i])] = c.code[i] << 6 | c.length[i];
  const uint64_t rlc = c.code[values] << 6 | c.length[values];

  // Room: the table at most 14 bits a present symbol and 14 more for the gap before it, the data
  // at most every value's own code.
  uint64_t data_bits = 0;
  for (size_t i = 0; i < c.freq.size(); ++i) data_bits += c.freq[i] * c.length[i];
  const int im = c.symbol.front(), iM = c.symbol.back();
  const size_t table_room = (size_t(iM - im + 1) * 6 + c.symbol.size() * 14) / 8 + 8;
  const size_t start = out.size();
  out.resize(start + 20 + table_room + data_bits / 8 + 16);
  char* header = out.data() + start;
  MsbBits packed(header + 20);
  pack_lengths(c, packed);
  packed.finish();
  const size_t table_bytes = packed.bytes();
  MsbBits data(header + 20 + table_bytes);
  if (*std::max_element(c.length.begin(), c.length.end()) > 32)
    encode<true>(table.data(), rlc, runs.data(), run_count, data);
  else
    encode<false>(table.data(), rlc, runs.data(), run_count, data);
  const size_t bits = data.finish();
  store_le(header, uint32_t(im), 4);
  store_le(header + 4, uint32_t(iM), 4);
  store_le(header + 8, uint32_t(table_bytes), 4);
  store_le(header + 12, uint32_t(bits), 4);
  store_le(header + 16, 0, 4);
  const size_t written = 20 + table_bytes + (bits + 7) / 8;
  out.resize(start + written);
  return written;
}

}  // namespace sdfreel
