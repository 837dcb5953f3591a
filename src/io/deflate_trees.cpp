// Names follow zlib's trees.c, whose steps these are (see deflate_trees.h for why).
#include "io/deflate_trees.h"

#include <cstring>

namespace sdfreel::deflate {

namespace {

constexpr int MAX_BITS = 15, MAX_BL_BITS = 7, HEAP_SIZE = 2 * LITERAL_CODES + 1;
constexpr int REP_3_6 = 16, REPZ_3_10 = 17, REPZ_11_138 = 18;
constexpr int STORED_BLOCK = 0, STATIC_TREES = 1, DYN_TREES = 2;
constexpr uint8_t BL_ORDER[LENGTH_CODES] = {16, 17, 18, 0, 8,  7, 9,  6, 10, 5,
                                            11, 4,  12, 3, 13, 2, 14, 1, 15};
constexpr int EXTRA_LBITS[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr int EXTRA_DBITS[DISTANCE_CODES] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                             6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
constexpr int EXTRA_BLBITS[LENGTH_CODES] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                                            0, 0, 0, 0, 0, 0, 2, 3, 7};

uint32_t reversed(uint32_t code, int length) {
  uint32_t r = 0;
  for (int i = 0; i < length; ++i, code >>= 1) r = (r << 1) | (code & 1);
  return r;
}

// The canonical codes of symbols [0, last] from their lengths (RFC 1951 3.2.2, zlib's
// gen_codes), as BlockCodes holds them; `count[b]` is how many symbols are b bits long.
template <typename Length>
void canonical_codes(const uint16_t count[MAX_BITS + 1], const Length* lengths, int last,
                     uint32_t* symbol) {
  uint16_t next[MAX_BITS + 1] = {};
  for (int bits = 1, code = 0; bits <= MAX_BITS; ++bits)
    next[bits] = uint16_t(code = (code + count[bits - 1]) << 1);
  for (int n = 0; n <= last; ++n)
    if (const int length = lengths[n]; length != 0)
      symbol[n] = reversed(next[length]++, length) | uint32_t(length) << 16;
}

// The fixed code of RFC 1951 3.2.6 (zlib's static_ltree and static_dtree).
struct StaticCodes {
  uint8_t lengths[288], distance_lengths[DISTANCE_CODES];
  BlockCodes codes;
  StaticCodes() {
    uint16_t count[MAX_BITS + 1] = {};
    for (int n = 0; n < 288; ++n) {
      lengths[n] = n < 144 ? 8 : n < 256 ? 9 : n < 280 ? 7 : 8;
      ++count[lengths[n]];
    }
    canonical_codes(count, lengths, 287, codes.symbol);
    std::memset(distance_lengths, 5, sizeof distance_lengths);
  }
};

const StaticCodes& static_codes() {
  static const StaticCodes s;
  return s;
}

struct TreeKind {
  const uint8_t* static_lengths;  // null for the code-length tree
  const int* extra;
  int extra_base, elems, max_length;
};

// zlib's ct_data array (Freq/Code and Dad/Len are unions there; here each has its own array,
// read only where zlib reads the member last written).
struct Tree {
  uint32_t freq[HEAP_SIZE] = {};
  uint16_t len[HEAP_SIZE] = {}, dad[HEAP_SIZE] = {};
  uint32_t code[HEAP_SIZE] = {};  // as BlockCodes holds them
  int max_code = -1;
};

// The parts of zlib's deflate_state that building trees uses.
struct State {
  // zlib's heap array: its priority queue [1, heap_len] is `queue` here, each entry the node's
  // order (frequency then depth, zlib's smaller()) above its number, so a compare reads one
  // entry; the nodes taken out, from heap_max up, stay in `heap`.
  uint64_t queue[HEAP_SIZE] = {};
  int heap[HEAP_SIZE] = {};
  int heap_len = 0, heap_max = 0;
  uint8_t depth[HEAP_SIZE] = {};
  uint16_t bl_count[MAX_BITS + 1] = {};
  uint64_t opt_len = 0, static_len = 0;  // zlib's ulg: the wrap of opt_len-- cancels as there
  Tree bl_tree;

  uint64_t entry(const Tree& t, int n) const {
    return uint64_t(t.freq[n] << 8 | depth[n]) << 32 | uint32_t(n);
  }
  static bool smaller(uint64_t a, uint64_t b) { return a >> 32 <= b >> 32; }
  static int node_of(uint64_t e) { return int(uint32_t(e)); }

  // zlib's pqdownheap, the smaller child chosen without a branch (its compares mispredicted
  // half the time: most of a block's tree time).
  void pqdownheap(int k) {
    const uint64_t v = queue[k];
    int j = k << 1;
    while (j <= heap_len) {
      uint64_t child = queue[j];
      if (j < heap_len) {
        const uint64_t right = queue[j + 1];
        const bool take_right = smaller(right, child);
        j += take_right;
        child = take_right ? right : child;
      }
      if (smaller(v, child)) break;
      queue[k] = child;
      k = j;
      j <<= 1;
    }
    queue[k] = v;
  }

  void gen_bitlen(Tree& t, const TreeKind& kind) {
    for (uint16_t& c : bl_count) c = 0;
    t.len[heap[heap_max]] = 0;  // the root
    int h = heap_max + 1, overflow = 0;
    for (; h < HEAP_SIZE; ++h) {
      const int n = heap[h];
      int bits = t.len[t.dad[n]] + 1;
      if (bits > kind.max_length) bits = kind.max_length, ++overflow;
      t.len[n] = uint16_t(bits);
      if (n > t.max_code) continue;  // not a leaf
      ++bl_count[bits];
      const int xbits = n >= kind.extra_base ? kind.extra[n - kind.extra_base] : 0;
      const uint64_t f = t.freq[n];
      opt_len += f * uint64_t(bits + xbits);
      if (kind.static_lengths) static_len += f * uint64_t(kind.static_lengths[n] + xbits);
    }
    if (overflow == 0) return;
    do {  // move the overflowed leaves up, as zlib does
      int bits = kind.max_length - 1;
      while (bl_count[bits] == 0) --bits;
      --bl_count[bits];
      bl_count[bits + 1] += 2;
      --bl_count[kind.max_length];
      overflow -= 2;
    } while (overflow > 0);
    for (int bits = kind.max_length; bits != 0; --bits) {
      int n = bl_count[bits];
      while (n != 0) {
        const int m = heap[--h];
        if (m > t.max_code) continue;
        if (t.len[m] != bits) {
          opt_len += (uint64_t(bits) - t.len[m]) * t.freq[m];
          t.len[m] = uint16_t(bits);
        }
        --n;
      }
    }
  }

  void build_tree(Tree& t, const TreeKind& kind) {
    heap_len = 0, heap_max = HEAP_SIZE;
    int max_code = -1;
    for (int n = 0; n < kind.elems; ++n) {
      if (t.freq[n] != 0) {
        max_code = n;
        depth[n] = 0;
        queue[++heap_len] = entry(t, n);
      } else {
        t.len[n] = 0;
      }
    }
    while (heap_len < 2) {  // at least two codes, even for a tree nothing uses
      const int node = max_code < 2 ? ++max_code : 0;
      t.freq[node] = 1;
      depth[node] = 0;
      queue[++heap_len] = entry(t, node);
      --opt_len;
      if (kind.static_lengths) static_len -= kind.static_lengths[node];
    }
    t.max_code = max_code;
    for (int n = heap_len / 2; n >= 1; --n) pqdownheap(n);
    int node = kind.elems;
    do {
      const int n = node_of(queue[1]);
      queue[1] = queue[heap_len--];
      pqdownheap(1);
      const int m = node_of(queue[1]);
      heap[--heap_max] = n;
      heap[--heap_max] = m;
      t.freq[node] = t.freq[n] + t.freq[m];
      depth[node] = uint8_t((depth[n] >= depth[m] ? depth[n] : depth[m]) + 1);
      t.dad[n] = t.dad[m] = uint16_t(node);
      queue[1] = entry(t, node++);
      pqdownheap(1);
    } while (heap_len >= 2);
    heap[--heap_max] = node_of(queue[1]);
    gen_bitlen(t, kind);
    canonical_codes(bl_count, t.len, t.max_code, t.code);
  }

  // The code lengths' run-length symbols, counted (zlib's scan_tree) or sent (send_tree).
  template <typename Symbol>
  static void runs(Tree& t, int max_code, Symbol&& symbol) {
    int prevlen = -1, nextlen = t.len[0], count = 0, max_count = 7, min_count = 4;
    if (nextlen == 0) max_count = 138, min_count = 3;
    for (int n = 0; n <= max_code; ++n) {
      const int curlen = nextlen;
      nextlen = t.len[n + 1];
      if (++count < max_count && curlen == nextlen) continue;
      if (count < min_count) {
        for (; count > 0; --count) symbol(curlen, 0);
      } else if (curlen != 0) {
        if (curlen != prevlen) symbol(curlen, 0), --count;
        symbol(REP_3_6, count - 3);
      } else if (count <= 10) {
        symbol(REPZ_3_10, count - 3);
      } else {
        symbol(REPZ_11_138, count - 11);
      }
      count = 0;
      prevlen = curlen;
      if (nextlen == 0) {
        max_count = 138, min_count = 3;
      } else if (curlen == nextlen) {
        max_count = 6, min_count = 3;
      } else {
        max_count = 7, min_count = 4;
      }
    }
  }

  void scan_tree(Tree& t) {
    t.len[t.max_code + 1] = 0xffff;  // guard
    runs(t, t.max_code, [&](int s, int) { ++bl_tree.freq[s]; });
  }

  void send_tree(BitWriter& out, Tree& t) {
    runs(t, t.max_code, [&](int s, int repeat) {
      out.put_symbol(bl_tree.code[s]);
      if (s == REP_3_6) out.put(uint32_t(repeat), 2);
      if (s == REPZ_3_10) out.put(uint32_t(repeat), 3);
      if (s == REPZ_11_138) out.put(uint32_t(repeat), 7);
    });
  }

  int build_bl_tree(Tree& literals, Tree& distances) {
    scan_tree(literals);
    scan_tree(distances);
    build_tree(bl_tree, TreeKind{nullptr, EXTRA_BLBITS, 0, LENGTH_CODES, MAX_BL_BITS});
    int max_blindex = LENGTH_CODES - 1;
    for (; max_blindex >= 3; --max_blindex)
      if (bl_tree.len[BL_ORDER[max_blindex]] != 0) break;
    opt_len += 3 * (uint64_t(max_blindex) + 1) + 5 + 5 + 4;
    return max_blindex;
  }
};

}  // namespace

bool start_block(BitWriter& out, const uint32_t counts[256], const uint8_t* data, size_t size,
                 bool last, BlockCodes& codes) {
  const StaticCodes& fixed = static_codes();
  out.room(size + 1024);  // a stored block, or the trees (under 300 bytes)
  State s;
  Tree literals, distances;
  for (int i = 0; i < 256; ++i) literals.freq[i] = counts[i];
  literals.freq[END_OF_BLOCK] = 1;
  s.build_tree(literals, TreeKind{fixed.lengths, EXTRA_LBITS, 257, LITERAL_CODES, MAX_BITS});
  s.build_tree(distances,
               TreeKind{fixed.distance_lengths, EXTRA_DBITS, 0, DISTANCE_CODES, MAX_BITS});
  const int max_blindex = s.build_bl_tree(literals, distances);
  uint64_t opt_lenb = (s.opt_len + 3 + 7) >> 3;
  const uint64_t static_lenb = (s.static_len + 3 + 7) >> 3;
  if (static_lenb <= opt_lenb) opt_lenb = static_lenb;
  if (size + 4 <= opt_lenb) {
    out.put((STORED_BLOCK << 1) + last, 3);
    out.align();
    const uint16_t length = uint16_t(size), complement = uint16_t(~length);
    for (uint16_t v : {length, complement}) out.byte(uint8_t(v)), out.byte(uint8_t(v >> 8));
    for (size_t i = 0; i < size; ++i) out.byte(data[i]);
    return false;
  }
  if (static_lenb == opt_lenb) {
    out.put((STATIC_TREES << 1) + last, 3);
    codes = fixed.codes;
    return true;
  }
  out.put((DYN_TREES << 1) + last, 3);
  const int lcodes = literals.max_code + 1, dcodes = distances.max_code + 1;
  out.put(uint32_t(lcodes - 257), 5);
  out.put(uint32_t(dcodes - 1), 5);
  out.put(uint32_t(max_blindex + 1 - 4), 4);
  for (int rank = 0; rank <= max_blindex; ++rank) out.put(s.bl_tree.len[BL_ORDER[rank]], 3);
  s.send_tree(out, literals);
  s.send_tree(out, distances);
  for (int n = 0; n < 288; ++n)  // past max_code: unused
    codes.symbol[n] = n <= literals.max_code ? literals.code[n] : 0;
  return true;
}

}  // namespace sdfreel::deflate
