// kiln compile --scene / --usage: build exactly the variants a scene (or a recorded run) looks
// up. The lookups come from the runtime itself: kiln-render plans the scene's frame without a GPU
// (kiln render --dry-run) over a pack of the shaders without variants, and writes every lookup
// with who made it; the compiler builds those (CompileOptions::requests). --verify-scene replays
// the plan against the stripped pack and fails on any lookup it misses.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "kiln/base/files.h"
#include "kiln/material/sidecar.h"

extern char** environ;

namespace kiln::cli {
namespace {
namespace fs = std::filesystem;

// A folder for the skeleton pack, the stripped pack under verification and the usage files;
// removed with everything in it.
class ScratchFolder {
  public:
    ScratchFolder() {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/kiln-scene-XXXXXX";
        if (mkdtemp(pattern.data()) != nullptr) {
            path_ = pattern;
        }
    }
    ~ScratchFolder() {
        std::error_code ec;
        if (!path_.empty()) {
            fs::remove_all(path_, ec);
        }
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    const std::string& path() const { return path_; }

  private:
    std::string path_;
};

// Runs kiln-render with `args`; its stdout is dropped, its stderr (JSON diagnostics) returned.
Result<std::pair<int, std::string>> RunRenderTool(const std::vector<std::string>& args) {
    const std::string tool = RenderToolPath();
    int pipe_fds[2];
    if (pipe(pipe_fds) != 0) {
        return Error{DiagCode::kRendererUnavailable, std::string("pipe: ") + std::strerror(errno)};
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
    posix_spawn_file_actions_addclose(&actions, pipe_fds[1]);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(tool.c_str()));
    for (const std::string& a : args) {
        argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, tool.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(pipe_fds[1]);
    if (spawned != 0) {
        close(pipe_fds[0]);
        return Error{DiagCode::kRendererUnavailable,
                     "cannot run the renderer '" + tool +
                         "' to plan the scene: " + std::strerror(spawned) +
                         "; kiln compile --scene needs kiln-render, installed beside kiln"};
    }
    std::string err;
    char buf[65536];
    for (ssize_t n; (n = read(pipe_fds[0], buf, sizeof buf)) != 0;) {
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n < 0) {
            break;
        }
        err.append(buf, size_t(n));
    }
    close(pipe_fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status)) {
        return Error{DiagCode::kRendererUnavailable,
                     "the renderer '" + tool + "' ended abnormally while planning the scene"};
    }
    return std::make_pair(WEXITSTATUS(status), std::move(err));
}

// One scene's dry run over `packs`: its lookups, or false after reporting why not. With
// `allow_missing` lookups of variants the packs lack are recorded, not errors; without it they
// are K4019 errors. Warnings are kept only when `keep_warnings`.
bool DryRun(const std::string& scene,
            const std::vector<std::string>& packs,
            const std::vector<std::string>& sidecars,
            const SceneStripFlags& flags,
            const std::string& usage_path,
            bool allow_missing,
            bool keep_warnings,
            pack::UsageLog& out,
            DiagnosticList& diags) {
    std::vector<std::string> args = {"--diagnostics-format",
                                     "json",
                                     "render",
                                     scene,
                                     "--dry-run",
                                     "--usage",
                                     usage_path,
                                     "--pixel-lights",
                                     std::to_string(flags.pixel_lights),
                                     "--light-mode",
                                     flags.light_mode,
                                     "--path",
                                     flags.path,
                                     "--shadows",
                                     flags.shadows};
    for (const std::string& p : packs) {
        args.insert(args.end(), {"--pack", p});
    }
    for (const std::string& s : sidecars) {
        args.insert(args.end(), {"--materials", s});
    }
    if (allow_missing) {
        args.push_back("--allow-missing");
    }
    Result<std::pair<int, std::string>> ran = RunRenderTool(args);
    if (!ran) {
        diags.Error(ran.error().code, scene, kNoPosition, ran.error().message);
        return false;
    }
    const auto& [code, err] = ran.value();
    Result<DiagnosticList> reported = ParseDiagnosticsJson(err);
    if (!reported) {
        diags.Error(DiagCode::kRendererUnavailable, scene, kNoPosition,
                    "the renderer's dry run of the scene printed no diagnostics Kiln can read "
                    "(exit status " +
                        std::to_string(code) + ")");
        return false;
    }
    for (const Diagnostic& d : reported.value().all()) {
        if (d.severity < Severity::kError && !keep_warnings) {
            continue;
        }
        const bool miss = d.code == DiagCode::kMissingVariant;
        Diagnostic& copy = diags.Add(
            d.severity, miss ? DiagCode::kSceneVerifyFailed : d.code, d.file, d.range,
            miss ? "the stripped pack misses a lookup of the scene: " + d.message : d.message);
        copy.notes = d.notes;
    }
    if (code != 0) {
        if (!reported.value().has_errors()) {
            diags.Error(DiagCode::kRendererUnavailable, scene, kNoPosition,
                        "the renderer's dry run of the scene failed (exit status " +
                            std::to_string(code) + ")");
        }
        return false;
    }
    Result<std::string> text = base::ReadRegularFile(usage_path, 256u << 20);
    Result<pack::UsageLog> log =
        text ? pack::ParseUsageFile(text.value()) : Result<pack::UsageLog>(text.error());
    if (!log) {
        diags.Error(log.error().code, usage_path, kNoPosition, log.error().message);
        return false;
    }
    for (pack::UsageEntry& e : log.value().lookups) {
        out.lookups.push_back(std::move(e));
    }
    for (pack::UsageMaterial& m : log.value().materials) {
        out.materials.push_back(std::move(m));
    }
    return true;
}

// The packs a dry run searches: `first`, then the shipped pack when it exists (glTF materials
// without a sidecar use its Kiln/StandardMetallic, as kiln render does).
std::vector<std::string> DryRunPacks(const std::string& first) {
    std::vector<std::string> packs = {first};
    std::error_code ec;
    const std::string shipped = ShippedPackPath();
    if (fs::is_regular_file(shipped, ec)) {
        packs.push_back(shipped);
    }
    return packs;
}

}  // namespace

namespace {

// A sidecar and the .material files it maps, or a .material file.
void AddMaterialInputs(const std::string& path, std::vector<std::string>& out) {
    out.push_back(path);
    if (!path.ends_with(".kiln.json"))
        return;
    if (Result<material::MaterialSidecar> sidecar = material::ReadMaterialSidecar(path)) {
        for (const auto& [name, file] : sidecar.value().materials)
            out.push_back(file);
    }
}

}  // namespace

std::vector<std::string> SceneStripInputs(const SceneStripFlags& flags,
                                          const std::vector<std::string>& sidecars) {
    std::vector<std::string> out = flags.usage_files;
    for (const std::string& sidecar : sidecars)
        AddMaterialInputs(sidecar, out);
    for (const std::string& scene : flags.scenes) {
        out.push_back(scene);
        // The sidecar the renderer reads beside the scene.
        const std::string beside =
            (fs::path(scene).parent_path() / fs::path(scene).stem()).string() + ".kiln.json";
        if (fs::exists(beside))
            AddMaterialInputs(beside, out);
        // The files the scene's buffers and images name (kiln-render reads them in the dry run):
        // the JSON of a .gltf, or the JSON chunk of a .glb.
        Result<std::string> bytes = base::ReadRegularFile(scene, uint64_t{1} << 30);
        if (!bytes)
            continue;  // the dry run reports it
        std::string_view json = bytes.value();
        if (json.size() >= 20 && json.substr(0, 4) == "glTF") {
            uint32_t length = 0;
            std::memcpy(&length, json.data() + 12, 4);  // little-endian, as glTF is
            json = json.substr(20, std::min<size_t>(length, json.size() - 20));
        }
        const nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
        if (!doc.is_object())
            continue;
        for (const char* list : {"buffers", "images"}) {
            const auto it = doc.find(list);
            if (it == doc.end() || !it->is_array())
                continue;
            for (const nlohmann::json& item : *it) {
                const auto uri = item.is_object() ? item.find("uri") : item.end();
                if (uri == item.end() || !uri->is_string())
                    continue;
                const std::string name = uri->get<std::string>();
                if (name.rfind("data:", 0) != 0 && name.find("://") == std::string::npos)
                    out.push_back((fs::path(scene).parent_path() / name).string());
            }
        }
    }
    return out;
}

void AddSceneStripOptions(CLI::App& cmd, SceneStripFlags& f) {
    cmd.add_option("--scene", f.scenes,
                   "Build only the variants this glTF scene looks up when rendered (its "
                   "<scene>.kiln.json, or --materials, assigns material instances)")
        ->option_text("SCENE.gltf");
    cmd.add_option("--usage", f.usage_files,
                   "Build only the variants this usage file (kiln render --usage, or an "
                   "engine's) looks up; with --scene, those of both")
        ->option_text("USAGE.json");
    // kiln-render checks the name: the paths are the runtime's (registered there).
    cmd.add_option("--path", f.path,
                   "The render path the scene is drawn with, as kiln render's: forward, "
                   "deferred, or another path kiln-render registers (default forward)")
        ->option_text("NAME");
    cmd.add_option("--pixel-lights", f.pixel_lights,
                   "Additive per-light passes per object at most, as kiln render's (default 4)")
        ->option_text("N");
    cmd.add_option("--light-mode", f.light_mode,
                   "How lights beyond the main one light objects, as kiln render's (default "
                   "auto)")
        ->check(CLI::IsMember({"auto", "pixel", "vertex", "sh"}, CLI::ignore_case))
        ->option_text("auto|pixel|vertex|sh");
    cmd.add_option("--shadows", f.shadows,
                   "The shadows the scene is drawn with, as kiln render's: their casters, "
                   "collector and receiver variants are kept (default off)")
        ->check(CLI::IsMember({"off", "hard", "soft"}, CLI::ignore_case))
        ->option_text("off|hard|soft");
    cmd.add_flag("--explain", f.explain,
                 "Print what was kept and why, what was left out, and what that saved");
    cmd.add_flag("--explain-json", f.explain_json, "The same as JSON on stdout");
    cmd.add_flag("--verify-scene", f.verify,
                 "Replay each scene's lookups against the stripped pack; any miss is an error "
                 "and no pack is written");
}

bool PlanRequests(const SceneStripFlags& flags,
                  const std::vector<std::string>& shaders,
                  const std::vector<std::string>& sidecars,
                  CompileOptions& options,
                  DiagnosticList& diags) {
    pack::UsageLog log;
    for (const std::string& path : flags.usage_files) {
        Result<std::string> text = base::ReadRegularFile(path, 256u << 20);
        Result<pack::UsageLog> read =
            text ? pack::ParseUsageFile(text.value()) : Result<pack::UsageLog>(text.error());
        if (!read) {
            diags.Error(read.error().code, path, kNoPosition, read.error().message);
            continue;
        }
        log.lookups.insert(log.lookups.end(), read.value().lookups.begin(),
                           read.value().lookups.end());
        log.materials.insert(log.materials.end(), read.value().materials.begin(),
                             read.value().materials.end());
    }
    if (!flags.scenes.empty() && !diags.has_errors()) {
        const CompileOutput skeleton = BuildSkeletonPack(shaders, options, diags);
        if (!skeleton.ok) {
            return false;
        }
        ScratchFolder scratch;
        const std::string pack_path = scratch.path() + "/skeleton.kpack";
        if (scratch.path().empty() ||
            !base::WriteFileAtomically(pack_path, std::span<const uint8_t>(skeleton.pack)).ok()) {
            diags.Error(DiagCode::kCannotWriteFile, pack_path, kNoPosition,
                        "cannot write the scene's planning pack in a temporary folder");
            return false;
        }
        for (size_t i = 0; i < flags.scenes.size(); ++i) {
            DryRun(flags.scenes[i], DryRunPacks(pack_path), sidecars, flags,
                   scratch.path() + "/usage" + std::to_string(i) + ".json", true, true, log, diags);
        }
    }
    options.requests = std::move(log);
    return !diags.has_errors();
}

bool VerifyScenes(const SceneStripFlags& flags,
                  const std::vector<uint8_t>& pack,
                  const std::vector<std::string>& sidecars,
                  DiagnosticList& diags) {
    if (!flags.verify || flags.scenes.empty()) {
        return true;
    }
    ScratchFolder scratch;
    const std::string pack_path = scratch.path() + "/stripped.kpack";
    if (scratch.path().empty() ||
        !base::WriteFileAtomically(pack_path, std::span<const uint8_t>(pack)).ok()) {
        diags.Error(DiagCode::kCannotWriteFile, pack_path, kNoPosition,
                    "cannot write the stripped pack in a temporary folder to verify it");
        return false;
    }
    bool ok = true;
    for (size_t i = 0; i < flags.scenes.size(); ++i) {
        pack::UsageLog ignored;
        ok = DryRun(flags.scenes[i], DryRunPacks(pack_path), sidecars, flags,
                    scratch.path() + "/verify" + std::to_string(i) + ".json", false, false, ignored,
                    diags) &&
             ok;
    }
    return ok;
}

}  // namespace kiln::cli
