// SPDX-License-Identifier: GPL-3.0-or-later
// Four primitives at once (AVX2) for the leaf scans of the envelope searches,
// where the processor has AVX2: the kernels of PrimitivePairs.h on two blocks
// of two at a time, with the same operations in the same order, so the values
// are bit-identical to theirs (and to the scalar CompactValue). Chosen at run
// time; PrimitiveQuads.cxx is the only translation unit with AVX2 code, and
// it includes no C++ library header, so that no inline function compiled for
// AVX2 can be picked by the linker for the rest of the program.
#ifndef medialaxis_PrimitiveQuads_h
#define medialaxis_PrimitiveQuads_h

namespace medialaxis
{
namespace quads
{
/// The values at p of the records in `blocks` consecutive blocks of two
/// (PrimitivePairs.h layout), into out[0 .. 2 blocks); a padding lane's
/// value included.
using BlockValues = void (*)(const double* block, int blocks, const double* p, double* out);

/// The AVX2 kernels for round and slab blocks, or null without AVX2.
BlockValues RoundBlockValues();
BlockValues SlabBlockValues();
}
}

#endif
