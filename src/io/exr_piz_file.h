#pragma once
// A scanline EXR with PIZ compression, byte for byte as Imf::OutputFile writes it, its 32-line
// chunks compressed side by side on sdfreel's threads (io/exr_piz.h) instead of one after another:
// the last frame of a run, which no render overlaps, waits for its EXR. OpenEXR itself writes the
// magic number, the version, the header and the offset table's room (its own bytes); the chunks
// follow in order, each stored raw where PIZ would not make it smaller, as OpenEXR does.
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>

#include <vector>

namespace sdfreel {

// The file of `header` (PIZ, scanlines, increasing y, sampling 1) with `frame`'s pixels: each
// channel's slice of the channel's own type, or float for a half channel (rounded to nearest even
// by Imath: the file OpenEXR writes from those halves); a channel without a slice is zeros.
std::vector<char> encode_piz_exr(const Imf::Header& header, const Imf::FrameBuffer& frame);

}  // namespace sdfreel
