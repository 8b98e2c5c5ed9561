// Every library op's definition and semantics: the structs named in
// SHADETREE_LIBRARY_OPS (nodes/op_id.h). Included by the bindings that are
// generated from the op list: the registry, the interpreter's dispatch,
// the JIT's op library and (as source) the C++ that emit --cpp writes.
#pragma once

#include "nodes/ops/arithmetic.h"
#include "nodes/ops/conditionals.h"
#include "nodes/ops/derivatives.h"
#include "nodes/ops/generators.h"
#include "nodes/ops/soft_objects.h"
#include "nodes/ops/splines.h"
#include "nodes/ops/vectors.h"
