#include "image/png_runs.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <exception>
#include <thread>

namespace twinraster::png_runs {

namespace {

// Bits in deflate's order: each value's least significant bit first, packed from each byte's
// least significant bit.
class BitWriter {
 public:
  explicit BitWriter(std::vector<std::uint8_t>& out) : out_(out) {}
  void Put(std::uint32_t value, int count) {  // count <= 32
    bits_ |= std::uint64_t{value} << count_;
    count_ += count;
    if (count_ < 32) return;
    const auto word = static_cast<std::uint32_t>(bits_);
    const std::size_t at = out_.size();
    out_.resize(at + 4);
    std::memcpy(out_.data() + at, &word, 4);  // little-endian hosts only (x86-64, aarch64)
    bits_ >>= 32;
    count_ -= 32;
  }
  void Finish() {  // pads the last byte with zeros
    for (; count_ > 0; count_ -= 8, bits_ >>= 8) out_.push_back(static_cast<std::uint8_t>(bits_));
    count_ = 0;
  }
  // The bits written so far, before Finish pads them.
  std::size_t BitCount() const { return out_.size() * 8 + static_cast<std::size_t>(count_); }

 private:
  std::vector<std::uint8_t>& out_;
  std::uint64_t bits_ = 0;
  int count_ = 0;
};

// A literal byte (length 0) or a repeat of `length` bytes from `distance` back (1 or 4).
struct Token {
  std::uint16_t length;
  std::uint16_t value;  // the literal, or the distance
};

constexpr int kMinMatch = 3, kMaxMatch = 258;
constexpr int kEndOfBlock = 256, kLiteralCodes = 286, kDistanceCodes = 30;

// RFC 1951, 3.2.5: match length -> symbol 257..285 with its extra bits above a base.
struct LengthCode {
  std::uint16_t symbol = 0, base = 0;
  std::uint8_t extra = 0;
};
constexpr std::array<LengthCode, kMaxMatch + 1> MakeLengthCodes() {
  constexpr int kBase[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                             31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
  constexpr int kExtra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
  std::array<LengthCode, kMaxMatch + 1> codes{};
  for (int c = 0; c < 29; ++c) {
    const int end = c == 28 ? kMaxMatch + 1 : std::min(kBase[c + 1], kMaxMatch);  // 258 has a code of its own
    for (int length = kBase[c]; length < end; ++length) {
      codes[static_cast<std::size_t>(length)] = {static_cast<std::uint16_t>(257 + c),
                                                 static_cast<std::uint16_t>(kBase[c]),
                                                 static_cast<std::uint8_t>(kExtra[c])};
    }
  }
  return codes;
}
constexpr std::array<LengthCode, kMaxMatch + 1> kLengthCodes = MakeLengthCodes();

// Distance 1 is distance code 0 and distance 4 code 3, neither with extra bits.
int DistanceCode(int distance) { return distance == 1 ? 0 : 3; }

// How many bytes from p equal those from p - distance, up to `limit`, 8 at a time.
std::size_t RepeatLength(const std::uint8_t* p, std::size_t distance, std::size_t limit) {
  const std::uint8_t* before = p - distance;  // n - distance would wrap below zero
  std::size_t n = 0;
  for (; n + 8 <= limit; n += 8) {
    std::uint64_t a, b;
    std::memcpy(&a, p + n, 8);
    std::memcpy(&b, before + n, 8);
    if (a != b) return n + static_cast<std::size_t>(__builtin_ctzll(a ^ b) >> 3);  // little-endian
  }
  while (n < limit && p[n] == before[n]) ++n;
  return n;
}

// Greedy: at each byte of data[begin, end), the longer repeat of the byte before or the pixel
// before (which may lie before `begin`: a block may look back into the one before it), if 3 or more.
void Tokenize(std::span<const std::uint8_t> data, std::size_t begin, std::size_t end, std::vector<Token>& tokens) {
  tokens.clear();
  for (std::size_t i = begin; i < end;) {
    const std::size_t limit = std::min<std::size_t>(kMaxMatch, end - i);
    std::size_t best = 0, distance = 0;
    for (const std::size_t d : {std::size_t{1}, std::size_t{4}}) {
      if (i < d || best == limit) continue;
      const std::size_t n = RepeatLength(data.data() + i, d, limit);
      if (n > best) best = n, distance = d;
    }
    if (best >= kMinMatch) {
      tokens.push_back({static_cast<std::uint16_t>(best), static_cast<std::uint16_t>(distance)});
      i += best;
    } else {
      tokens.push_back({0, data[i]});
      ++i;
    }
  }
}

// Huffman code lengths for `frequency`, none longer than `limit`; unused symbols get 0. One used
// symbol (or none) gets a second, so that the code is complete, as inflaters expect.
std::vector<std::uint8_t> CodeLengths(std::vector<std::uint32_t> frequency, int limit) {
  std::vector<int> used;
  for (std::size_t s = 0; s < frequency.size(); ++s)
    if (frequency[s] != 0) used.push_back(static_cast<int>(s));
  if (used.size() < 2) {
    for (int s : {0, 1})
      frequency[static_cast<std::size_t>(s)] = std::max<std::uint32_t>(frequency[static_cast<std::size_t>(s)], 1);
    return CodeLengths(std::move(frequency), limit);
  }
  std::sort(used.begin(), used.end(), [&](int a, int b) {
    return frequency[std::size_t(a)] != frequency[std::size_t(b)]
               ? frequency[std::size_t(a)] < frequency[std::size_t(b)]
               : a < b;
  });
  // The tree by two queues (leaves by weight, then internal nodes as they are made), then depths.
  const std::size_t leaves = used.size(), nodes = 2 * leaves - 1;
  std::vector<std::uint64_t> weight(nodes);
  std::vector<std::size_t> parent(nodes, 0);
  for (std::size_t i = 0; i < leaves; ++i) weight[i] = frequency[std::size_t(used[i])];
  std::size_t next_leaf = 0, next_node = leaves;
  const auto lightest = [&](std::size_t made) {
    if (next_leaf < leaves && (next_node >= made || weight[next_leaf] <= weight[next_node])) return next_leaf++;
    return next_node++;
  };
  for (std::size_t made = leaves; made < nodes; ++made) {
    const std::size_t a = lightest(made), b = lightest(made);
    weight[made] = weight[a] + weight[b];
    parent[a] = parent[b] = made;
  }
  std::vector<int> depth(nodes, 0);
  for (std::size_t i = nodes - 1; i-- > 0;) depth[i] = depth[parent[i]] + 1;
  // Lengths over the limit become the limit; then the code, now overfull, is made complete again:
  // each step takes a leaf off the deepest level and moves one up a level into two.
  std::vector<std::uint32_t> at_length(static_cast<std::size_t>(limit) + 1, 0);
  for (std::size_t i = 0; i < leaves; ++i) at_length[std::size_t(std::min(depth[i], limit))]++;
  std::uint64_t kraft = 0;
  for (int l = 1; l <= limit; ++l) kraft += std::uint64_t{at_length[std::size_t(l)]} << (limit - l);
  for (; kraft > (std::uint64_t{1} << limit); --kraft) {
    at_length[std::size_t(limit)]--;
    for (int l = limit - 1; l > 0; --l) {
      if (at_length[std::size_t(l)] == 0) continue;
      at_length[std::size_t(l)]--;
      at_length[std::size_t(l) + 1] += 2;
      break;
    }
  }
  // The longest codes to the rarest symbols.
  std::vector<std::uint8_t> lengths(frequency.size(), 0);
  std::size_t i = 0;
  for (int l = limit; l >= 1; --l) {
    for (std::uint32_t k = 0; k < at_length[std::size_t(l)]; ++k) lengths[std::size_t(used[i++])] = std::uint8_t(l);
  }
  return lengths;
}

// Canonical codes (RFC 1951, 3.2.2), bit-reversed because Huffman codes go most significant bit first.
std::vector<std::uint16_t> CanonicalCodes(const std::vector<std::uint8_t>& lengths) {
  std::array<int, 16> count{}, next{};
  for (const std::uint8_t l : lengths) count[l]++;
  count[0] = 0;
  for (int l = 1, code = 0; l < 16; ++l) next[std::size_t(l)] = code = (code + count[std::size_t(l) - 1]) << 1;
  std::vector<std::uint16_t> codes(lengths.size(), 0);
  for (std::size_t s = 0; s < lengths.size(); ++s) {
    const int l = lengths[s];
    if (l == 0) continue;
    const int code = next[std::size_t(l)]++;
    int reversed = 0;
    for (int k = 0; k < l; ++k) reversed = (reversed << 1) | ((code >> k) & 1);
    codes[s] = static_cast<std::uint16_t>(reversed);
  }
  return codes;
}

struct Code {
  std::vector<std::uint8_t> lengths;
  std::vector<std::uint16_t> codes;
  void Put(BitWriter& bits, std::size_t symbol) const { bits.Put(codes[symbol], lengths[symbol]); }
};

Code MakeCode(std::vector<std::uint32_t> frequency, int limit) {
  Code code;
  code.lengths = CodeLengths(std::move(frequency), limit);
  code.codes = CanonicalCodes(code.lengths);
  return code;
}

// The dynamic block's header (RFC 1951, 3.2.7): the two codes' lengths, zero runs as symbols 17
// and 18, themselves Huffman coded.
void PutHeader(const Code& literals, const Code& distances, BitWriter& bits) {
  std::size_t literal_count = kLiteralCodes, distance_count = kDistanceCodes;
  while (literal_count > 257 && literals.lengths[literal_count - 1] == 0) --literal_count;
  while (distance_count > 1 && distances.lengths[distance_count - 1] == 0) --distance_count;
  std::vector<std::uint8_t> lengths(literals.lengths.begin(), literals.lengths.begin() + long(literal_count));
  lengths.insert(lengths.end(), distances.lengths.begin(), distances.lengths.begin() + long(distance_count));
  std::vector<std::pair<int, int>> symbols;  // (code-length symbol, its extra bits' value)
  for (std::size_t i = 0; i < lengths.size();) {
    std::size_t zeros = 0;
    while (lengths[i] == 0 && i + zeros < lengths.size() && lengths[i + zeros] == 0 && zeros < 138) ++zeros;
    if (zeros >= 11) symbols.push_back({18, int(zeros) - 11});
    if (zeros >= 3 && zeros < 11) symbols.push_back({17, int(zeros) - 3});
    if (zeros >= 3) {
      i += zeros;
      continue;
    }
    symbols.push_back({lengths[i++], 0});
  }
  std::vector<std::uint32_t> frequency(19, 0);
  for (const auto& [symbol, extra] : symbols) frequency[std::size_t(symbol)]++;
  const Code lengths_code = MakeCode(frequency, 7);
  constexpr int kOrder[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
  int order_count = 19;
  while (order_count > 4 && lengths_code.lengths[std::size_t(kOrder[order_count - 1])] == 0) --order_count;
  bits.Put(std::uint32_t(literal_count - 257), 5);
  bits.Put(std::uint32_t(distance_count - 1), 5);
  bits.Put(std::uint32_t(order_count - 4), 4);
  for (int k = 0; k < order_count; ++k) bits.Put(lengths_code.lengths[std::size_t(kOrder[k])], 3);
  for (const auto& [symbol, extra] : symbols) {
    lengths_code.Put(bits, std::size_t(symbol));
    if (symbol == 17) bits.Put(std::uint32_t(extra), 3);
    if (symbol == 18) bits.Put(std::uint32_t(extra), 7);
  }
}

// One block for data[begin, end) into `bits`, with its own Huffman codes.
void PutBlock(std::span<const std::uint8_t> data, std::size_t begin, std::size_t end, bool final, BitWriter& bits) {
  thread_local std::vector<Token> tokens;  // reused: fresh memory costs a page fault per 4 KiB
  Tokenize(data, begin, end, tokens);
  std::vector<std::uint32_t> literal_frequency(kLiteralCodes, 0), distance_frequency(kDistanceCodes, 0);
  for (const Token& t : tokens) {
    if (t.length == 0) {
      literal_frequency[t.value]++;
    } else {
      literal_frequency[kLengthCodes[t.length].symbol]++;
      distance_frequency[std::size_t(DistanceCode(t.value))]++;
    }
  }
  literal_frequency[kEndOfBlock] = 1;
  const Code literals = MakeCode(literal_frequency, 15), distances = MakeCode(distance_frequency, 15);
  bits.Put(final ? 1 : 0, 1);
  bits.Put(2, 2);  // dynamic Huffman codes
  PutHeader(literals, distances, bits);
  for (const Token& t : tokens) {
    if (t.length == 0) {
      literals.Put(bits, t.value);
      continue;
    }
    const LengthCode& c = kLengthCodes[t.length];
    literals.Put(bits, c.symbol);
    if (c.extra != 0) bits.Put(std::uint32_t(t.length - c.base), c.extra);
    distances.Put(bits, std::size_t(DistanceCode(t.value)));
  }
  literals.Put(bits, kEndOfBlock);
}

// Appends the first `count` bits of `tail` to `out`, whose last `used` bits (0..7) of its last
// byte are taken.
void AppendBits(std::vector<std::uint8_t>& out, int used, const std::vector<std::uint8_t>& tail, std::size_t count) {
  const std::size_t bytes = (count + 7) / 8;
  if (used == 0) {
    out.insert(out.end(), tail.begin(), tail.begin() + long(bytes));
    return;
  }
  for (std::size_t k = 0; k < bytes; ++k) {
    out.back() = static_cast<std::uint8_t>(out.back() | (tail[k] << used));
    if (k * 8 + std::size_t(8 - used) < count) out.push_back(static_cast<std::uint8_t>(tail[k] >> (8 - used)));
  }
}

// Below this a second thread costs more than it saves.
constexpr std::size_t kSplitBytes = std::size_t{1} << 20;

}  // namespace

void Deflate(std::span<const std::uint8_t> data, std::vector<std::uint8_t>& out) {
  const std::size_t half = data.size() >= kSplitBytes ? data.size() / 2 : data.size();
  std::vector<std::uint8_t> second;
  std::size_t second_bits = 0;
  std::exception_ptr failed;  // an exception may not leave a thread: it is carried over and rethrown
  std::thread helper;
  if (half < data.size()) {
    helper = std::thread([&] {
      try {
        BitWriter bits(second);
        PutBlock(data, half, data.size(), true, bits);
        second_bits = bits.BitCount();
        bits.Finish();
      } catch (...) {
        failed = std::current_exception();
      }
    });
  }
  // Joined on every path, an exception here included.
  const auto join = [&helper] {
    if (helper.joinable()) helper.join();
  };
  std::size_t first_bits = 0;
  try {
    BitWriter bits(out);
    PutBlock(data, 0, half, half == data.size(), bits);
    first_bits = bits.BitCount();
    bits.Finish();
  } catch (...) {
    join();
    throw;
  }
  join();
  if (failed) std::rethrow_exception(failed);
  if (half < data.size()) AppendBits(out, int(first_bits % 8), second, second_bits);
}

}  // namespace twinraster::png_runs
