// The JSON Schema (draft 2020-12) of the graph format, for editors to
// validate and complete graph files (`shadetree schema`). It is built from
// the tables the parser checks fields against (graph/format_fields.h), one
// variant per graph kind, and from the op table for the op names, so that
// it accepts what `check` accepts (tests/format_schema_test.py validates
// the gallery and the docs' examples with a real validator).
#pragma once

#include "graph/json_reader.h"

namespace shadetree {

json graph_format_schema();

}  // namespace shadetree
