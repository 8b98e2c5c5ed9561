// The constants an op instruction fixes (nodes/op_frame.h), laid out for
// the interpreter's frames: the lane and the interval evaluation of a
// program read the same.
#pragma once

#include "ir/shade_ir.h"
#include "nodes/op_frame.h"

namespace shadetree::interp {

// `instr` is an op instruction of `ir`; the result points into ir.data.
OpConstants op_constants(const ShadeIR& ir, const IrInstr& instr);

}  // namespace shadetree::interp
