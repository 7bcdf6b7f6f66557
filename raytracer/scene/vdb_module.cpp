#include "raytracer/scene/vdb_module.hpp"

#include <dlfcn.h>

#include <mutex>
#include <string>
#include <system_error>

#include "raytracer/input_error.hpp"

namespace sweeptrace {

namespace {

struct OpenedVdbModule {
    const SweeptraceVdbModule* table = nullptr;
    std::string error;  // why not, when table is null
};

OpenedVdbModule open_vdb_module() {
    OpenedVdbModule m;
    const std::filesystem::path path = vdb_module_path();
    if (path.empty()) {
        m.error = std::string("the VDB reader module ") + kVdbModuleFile +
                  " was not looked for: the running executable's folder is unknown (/proc/self/exe cannot be read)";
        return m;
    }
    const std::string head = "the VDB reader module " + path.string() + " did not load: ";
    // RTLD_NOW: a module that lacks a symbol fails here, by its name, not halfway through a read.
    // RTLD_LOCAL: its symbols and OpenVDB's stay out of the executable's namespace.
    void* const handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        m.error = head + reason_or(dlerror(), "dlopen gave no reason");
        return m;
    }
    using Entry = const SweeptraceVdbModule* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, kVdbModuleSymbol));
    if (!entry) {
        m.error = head + reason_or(dlerror(), "no entry point");
        return m;
    }
    const SweeptraceVdbModule* const table = entry();
    if (!table || table->abi != kVdbModuleAbi) {
        m.error = head + "its interface is version " + (table ? std::to_string(table->abi) : std::string("unknown")) +
                  ", this executable's is " + std::to_string(kVdbModuleAbi) + " (a module from another build)";
        return m;
    }
    m.table = table;
    return m;
}

}  // namespace

std::filesystem::path vdb_module_path() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec || exe.empty()) return {};
    return exe.parent_path() / kVdbModuleFile;
}

const SweeptraceVdbModule& vdb_module() {
    static std::once_flag once;
    static OpenedVdbModule opened;
    std::call_once(once, [] { opened = open_vdb_module(); });
    if (!opened.table) throw InputError(opened.error);
    return *opened.table;
}

}  // namespace sweeptrace
