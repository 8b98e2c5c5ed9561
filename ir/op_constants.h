// The constants an op instruction fixes (nodes/op_frame.h), as the
// interpreter's frames (lane, interval and dual) and the GLSL tracer read
// them.
#pragma once

#include "ir/shade_ir.h"
#include "nodes/op_frame.h"

namespace shadetree {

// `instr` is an op instruction of `ir`; the result points into ir.data.
OpConstants op_constants(const ShadeIR& ir, const IrInstr& instr);

}  // namespace shadetree
