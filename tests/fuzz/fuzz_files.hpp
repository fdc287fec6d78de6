#pragma once
// The in-memory "file system" the fuzz harnesses give the parsers: a few fixed files
// that seeds can refer to (mtllib a.mtl, "obj": "a.obj"), and the fuzz input itself
// under the name "self", so that one input exercises a nested parser too. Any other
// name fails the way a missing file does.
#include <string>
#include <string_view>

#include <hush/core/error.hpp>
#include <hush/tracer/obj_loader.hpp>

#include "fuzz_require.hpp"

namespace hush::fuzz {

inline tracer::FileReader memoryReader(std::string_view self) {
    return [self](const std::string& name) -> tracer::FileText {
        if (name == "a.mtl" || name == "models/a.mtl")
            return {name, "newmtl red\nKd 0.8 0.1 0.1\nNs 100\nnewmtl lamp\nKe 10 10 10\n"};
        if (name == "a.obj" || name == "models/a.obj")
            return {name, "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nusemtl red\nf 1 2 3\nusemtl lamp\nf 2 4 3\n"};
        if (name == "self" || name == "self.mtl" || name == "self.obj" || name == "models/self.obj")
            return {name, std::string(self)};
        throw Error(ErrorKind::NotFound, name + ": no such file");
    };
}

} // namespace hush::fuzz
