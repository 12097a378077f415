#include "files/png_runs.hpp"

#include "files/png_scanlines.hpp"

#include <libdeflate.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <exception>
#include <memory>
#include <span>
#include <thread>

namespace twinraster::files::png_runs {

namespace {

// Bits in deflate's order: each value's least significant bit first, packed from each byte's
// least significant bit.
class BitWriter {
 public:
  explicit BitWriter(std::vector<std::uint8_t>& out) : out_(out) { out_.resize(4096); }
  void Put(std::uint32_t value, int count) {  // count <= 32
    bits_ |= std::uint64_t{value} << count_;
    count_ += count;
    if (count_ < 32) return;
    if (at_ + 4 > out_.size()) out_.resize(2 * out_.size());
    const auto word = static_cast<std::uint32_t>(bits_);
    std::memcpy(out_.data() + at_, &word, 4);  // little-endian hosts only (x86-64, aarch64)
    at_ += 4;
    bits_ >>= 32;
    count_ -= 32;
  }
  // The bits written so far, before Finish pads them.
  std::size_t BitCount() const { return at_ * 8 + static_cast<std::size_t>(count_); }
  void Finish() {  // pads the last byte with zeros, and cuts `out` to what was written
    out_.resize(at_ + 8);
    for (; count_ > 0; count_ -= 8, bits_ >>= 8) out_[at_++] = static_cast<std::uint8_t>(bits_);
    out_.resize(at_);
    count_ = 0;
  }

 private:
  std::vector<std::uint8_t>& out_;  // written up to at_; its size is the room there is
  std::size_t at_ = 0;
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

// Whether neither the byte before p nor the pixel before it starts a repeat of kMinMatch (3)
// bytes at p: one 4-byte compare each, which decides most literals of a detailed frame at once.
// Needs 4 bytes before p and 4 from it.
bool NoRepeatAt(const std::uint8_t* p) {
  std::uint32_t here, byte_before, pixel_before;
  std::memcpy(&here, p, 4);
  std::memcpy(&byte_before, p - 1, 4);
  std::memcpy(&pixel_before, p - 4, 4);
  constexpr std::uint32_t kFirstThree = 0x00ffffff;  // little-endian: the bytes at p, p+1, p+2
  return ((here ^ byte_before) & kFirstThree) != 0 && ((here ^ pixel_before) & kFirstThree) != 0;
}

// Greedy: at each byte of `data`, the longer repeat of the byte before or the pixel before, if 3
// or more. It never looks before `data`, so that the halves of a frame can be filtered and
// encoded at once. `tokens` has room for one per byte; returns how many were written.
std::size_t Tokenize(std::span<const std::uint8_t> data, Token* tokens) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < data.size();) {
    if (i >= 4 && i + 4 <= data.size() && NoRepeatAt(data.data() + i)) {
      tokens[count++] = {0, data[i]};
      ++i;
      continue;
    }
    const std::size_t limit = std::min<std::size_t>(kMaxMatch, data.size() - i);
    std::size_t best = 0, distance = 0;
    for (const std::size_t d : {std::size_t{1}, std::size_t{4}}) {
      if (i < d || best == limit) continue;
      const std::size_t n = RepeatLength(data.data() + i, d, limit);
      if (n > best) best = n, distance = d;
    }
    if (best >= kMinMatch) {
      tokens[count++] = {static_cast<std::uint16_t>(best), static_cast<std::uint16_t>(distance)};
      i += best;
    } else {
      tokens[count++] = {0, data[i]};
      ++i;
    }
  }
  return count;
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

// One block of `tokens` into `bits`, with its own Huffman codes.
void PutBlock(std::span<const Token> tokens, bool final, BitWriter& bits) {
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

// Rows of a frame filtered, summed and deflated as one block.
struct Block {
  std::vector<std::uint8_t> bytes;  // the block, its last byte padded
  std::size_t bits = 0;             // its length in bits, before the padding
  std::uint32_t adler = 1;          // Adler-32 of the filtered rows
  std::size_t size = 0;             // filtered bytes
};

// Filtered bytes held at once: rows are filtered, summed and tokenized a few at a time through
// one small buffer, rather than the whole frame filtered into memory first, whose pages would cost
// more to touch than the encoding itself.
constexpr std::size_t kChunkBytes = std::size_t{64} << 10;

// Rows [first, last) of `image` filtered, summed and encoded; `final` marks the last block. A
// repeat never reaches back across a chunk's start.
Block EncodeRows(const Image& image, std::uint32_t first, std::uint32_t last, bool final) {
  const std::size_t row_bytes = png_scanlines::RowBytes(image);
  const auto rows_per_chunk = static_cast<std::uint32_t>(std::max<std::size_t>(1, kChunkBytes / row_bytes));
  std::vector<std::uint8_t> chunk(std::min<std::size_t>(rows_per_chunk, last - first) * row_bytes);
  Block block;
  block.size = row_bytes * (last - first);
  // Room for the most tokens there can be, not initialized: only what is written is touched.
  const std::unique_ptr<Token[]> tokens(new Token[block.size]);
  std::size_t count = 0;
  for (std::uint32_t y = first; y < last; y += rows_per_chunk) {
    const std::uint32_t end = std::min(last, y + rows_per_chunk);
    png_scanlines::FilterRows(image, y, end, chunk.data());
    const std::span<const std::uint8_t> filtered(chunk.data(), row_bytes * (end - y));
    block.adler = libdeflate_adler32(block.adler, filtered.data(), filtered.size());
    count += Tokenize(filtered, tokens.get() + count);
  }
  BitWriter bits(block.bytes);
  PutBlock({tokens.get(), count}, final, bits);
  block.bits = bits.BitCount();
  bits.Finish();
  return block;
}

// Runs `second` on a helper thread while `first` runs here. An exception may not leave a thread:
// the helper's is carried over and rethrown after the join, which happens on every path.
template <typename First, typename Second>
void OnTwoThreads(First first, Second second) {
  std::exception_ptr failed;
  std::thread helper([&] {
    try {
      second();
    } catch (...) {
      failed = std::current_exception();
    }
  });
  try {
    first();
  } catch (...) {
    helper.join();
    throw;
  }
  helper.join();
  if (failed) std::rethrow_exception(failed);
}

// Below this many filtered bytes a second thread costs more than it saves: in a fresh process its
// start alone outweighs half of a 600x600 frame's encoding. A 1080p frame is still split.
constexpr std::size_t kSplitBytes = std::size_t{2} << 20;

}  // namespace

std::vector<std::uint8_t> ZlibStream(const Image& image) {
  const bool split = png_scanlines::RowBytes(image) * image.height >= kSplitBytes && image.height >= 2;
  const std::uint32_t middle = split ? image.height / 2 : image.height;
  Block top, bottom;
  if (split) {
    OnTwoThreads([&] { top = EncodeRows(image, 0, middle, false); },
                 [&] { bottom = EncodeRows(image, middle, image.height, true); });
  } else {
    top = EncodeRows(image, 0, image.height, true);
  }
  std::vector<std::uint8_t> zlib;
  zlib.reserve(2 + (top.bits + bottom.bits) / 8 + 2 + 4);
  zlib.push_back(0x78);  // deflate, 32 KiB window
  zlib.push_back(0x01);  // no preset dictionary; the header's check bits
  AppendBits(zlib, 0, top.bytes, top.bits);
  std::uint32_t adler = top.adler;
  if (split) {
    AppendBits(zlib, int(top.bits % 8), bottom.bytes, bottom.bits);
    adler = static_cast<std::uint32_t>(adler32_combine(adler, bottom.adler, static_cast<z_off_t>(bottom.size)));
  }
  for (int shift = 24; shift >= 0; shift -= 8) zlib.push_back(static_cast<std::uint8_t>(adler >> shift));
  return zlib;
}

}  // namespace twinraster::files::png_runs
