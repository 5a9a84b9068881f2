#include "dataset_folder.h"

#include "flow_files.h"
#include "label_rig.h"

#include "dataset_coco.h"

#include "swell/dataset/atomic_file.h"
#include "swell/error.h"

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>

#include <signal.h>
#include <unistd.h>

namespace swell::app {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kDatasetFormat = "swell-dataset-1";

// Where the user's path would be made: the deepest part of it that exists.
fs::path deepestExisting(const fs::path& path)
{
    std::error_code error;
    for (fs::path part = fs::absolute(path, error); !part.empty(); part = part.parent_path()) {
        if (fs::exists(fs::status(part, error)))
            return part;
        if (part == part.parent_path())
            break;
    }
    return {};
}

[[noreturn]] void refuseOut(const std::string& message) { throw InputError({"--out"}, message); }

// Up to `count` bytes of `path` from `offset` (from the end when negative).
std::string bytesOf(const fs::path& path, std::streamoff offset, std::size_t count)
{
    std::ifstream in(path, std::ios::binary);
    if (offset < 0)
        in.seekg(offset, std::ios::end);
    else
        in.seekg(offset);
    std::string bytes(count, '\0');
    in.read(bytes.data(), std::streamsize(count));
    bytes.resize(in ? count : std::size_t(std::max<std::streamsize>(in.gcount(), 0)));
    return bytes;
}

std::uint32_t bigEndian32(const std::string& b, std::size_t at)
{
    return std::uint32_t(std::uint8_t(b[at])) << 24 | std::uint32_t(std::uint8_t(b[at + 1])) << 16 |
           std::uint32_t(std::uint8_t(b[at + 2])) << 8 | std::uint32_t(std::uint8_t(b[at + 3]));
}

// Why a PNG this program wrote is not whole at `size` ("" when it is): its
// signature, its header's size, and its last chunk, IEND (a file cut short
// lacks it).
std::string pngProblem(const fs::path& path, glm::ivec2 size)
{
    const std::string head = bytesOf(path, 0, 24);
    if (head.size() < 24 || head.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 || head.compare(12, 4, "IHDR") != 0)
        return "not a PNG";
    if (bigEndian32(head, 16) != std::uint32_t(size.x) || bigEndian32(head, 20) != std::uint32_t(size.y))
        return fmt::format("a PNG of {}x{} pixels, not {}x{}", bigEndian32(head, 16), bigEndian32(head, 20), size.x,
                           size.y);
    if (bytesOf(path, -12, 12) != std::string("\0\0\0\0IEND\xae\x42\x60\x82", 12))
        return "a PNG cut short (no IEND chunk at its end)";
    return {};
}

// Why an .npy file this program wrote does not hold `shape` of `descr` ("" when it does).
std::string npyProblem(const fs::path& path, const std::string& descr, const std::vector<int>& shape, std::size_t itemBytes)
{
    const std::string head = bytesOf(path, 0, 10);
    if (head.size() < 10 || head.compare(0, 8, std::string("\x93NUMPY\x01\x00", 8)) != 0)
        return "not an .npy file";
    const std::size_t headerBytes = std::size_t(std::uint8_t(head[8])) | std::size_t(std::uint8_t(head[9])) << 8;
    std::size_t elements = itemBytes;
    for (int n : shape)
        elements *= std::size_t(n);
    // The header this program writes for that array, to the byte.
    const char none = 0;
    const std::string expected = npyBytes(&none, 0, descr, shape);
    if (bytesOf(path, 0, expected.size()) != expected)
        return fmt::format("not a {} array of shape ({})", descr, fmt::join(shape, ", "));
    std::error_code error;
    const std::uintmax_t bytes = fs::file_size(path, error);
    if (error || bytes != 10 + headerBytes + elements)
        return fmt::format("{} bytes, not the {} its array holds (cut short?)", error ? 0 : bytes, 10 + headerBytes + elements);
    return {};
}

} // namespace

fs::path samplePng(const fs::path& out, int index) { return out / "samples" / fmt::format("{:06d}.png", index); }

int framesOf(const Sweep& sweep) { return sweep.clip ? sweep.clip->frames : 1; }

fs::path framePng(const fs::path& out, int index, const Sweep& sweep, int frame)
{
    if (!sweep.clip)
        return samplePng(out, index);
    return out / "samples" / fmt::format("{:06d}_{:05d}.png", index, frame);
}

std::vector<fs::path> frameFiles(const fs::path& out, int index, const Sweep& sweep, int frame,
                                 const std::string& camera)
{
    const fs::path png = rigCameraPath(framePng(out, index, sweep, frame), camera);
    std::vector<fs::path> files = labelFilePaths(png); // .range.npy ... .labels.png, .amodal.npy, .json
    if (!sweep.labels)
        files = {files.back()};
    else if (sweep.clip)
        for (const fs::path& f : flowFilePaths(png))
            files.insert(files.end() - 1, f);
    files.insert(files.begin(), png);
    return files;
}

Json manifestJson(const Sweep& sweep, const Scene& base)
{
    Json manifest;
    manifest["format"] = kDatasetFormat;
    manifest["sweep_file"] = sweep.file.filename().string();
    manifest["sweep"] = sweep.text;
    manifest["count"] = sweep.count;
    manifest["seed"] = sweep.seed;
    manifest["size"] = {sweep.size.x, sweep.size.y};
    manifest["labels"] = sweep.labels;
    Json classes = Json::object();
    const std::vector<std::string> names = labelClassesOf(base);
    for (std::size_t i = 0; i < names.size(); ++i)
        if (!names[i].empty())
            classes[std::to_string(i)] = names[i];
    manifest["classes"] = classes;
    manifest["samples"] = "samples/NNNNNN.png, and beside each its labels (docs/LABELS.md); a sample is done when "
                          "its .json is there and its files are whole";
    if (sweep.clip) {
        // Stills' manifests stay as they were.
        manifest["clip"] = {{"frames", sweep.clip->frames},
                            {"fps", sweep.clip->fps},
                            {"frame_files", "samples/NNNNNN_FFFFF.png (frame F of sample N), and beside each its "
                                            "labels and its optical flow to the next frame (docs/LABELS.md); a "
                                            "sample is done when every frame's files are whole"}};
    }
    return manifest;
}

void checkOutputFolder(const fs::path& out, const Sweep& sweep)
{
    if (out.empty())
        refuseOut("the dataset's folder is empty: give a folder (made when missing)");
    std::error_code error;
    const fs::path existing = deepestExisting(out);
    if (existing.empty())
        refuseOut(fmt::format("cannot make '{}': no part of its path exists", out.string()));
    if (!fs::is_directory(existing, error))
        refuseOut(fmt::format("cannot make the dataset's folder '{}': '{}' is a file, not a folder", out.string(),
                              existing.string()));
    if (::access(existing.c_str(), W_OK | X_OK) != 0)
        refuseOut(fmt::format("cannot make or write the dataset's folder '{}': '{}' is not writable ({})", out.string(),
                              existing.string(), std::strerror(errno)));
    const fs::path samples = out / "samples", manifest = out / "manifest.json";
    if (fs::exists(fs::symlink_status(samples, error)) && !fs::is_directory(samples, error))
        refuseOut(fmt::format("'{}' is there and is not a folder", samples.string()));
    if (fs::is_directory(samples, error) && ::access(samples.c_str(), W_OK | X_OK) != 0)
        refuseOut(fmt::format("'{}' is not writable ({})", samples.string(), std::strerror(errno)));
    if (!fs::exists(fs::symlink_status(manifest, error)))
        return;
    if (!fs::is_regular_file(manifest, error))
        refuseOut(fmt::format("'{}' is there and is not a file: not this sweep's dataset", manifest.string()));
    Json existingManifest;
    try {
        existingManifest = Json::parse(readFileBytes(manifest));
    } catch (const std::exception& e) {
        refuseOut(fmt::format("'{}' is not a dataset's manifest ({}): give another folder", manifest.string(), e.what()));
    }
    if (!existingManifest.is_object() || existingManifest.value("format", "") != kDatasetFormat ||
        existingManifest.value("sweep", "") != sweep.text)
        refuseOut(fmt::format("'{}' holds another sweep's dataset (its manifest.json records a different sweep file): "
                              "give another folder",
                              out.string()));
}

void prepareOutputFolder(const fs::path& out, const Sweep& sweep, const Scene& base)
{
    std::error_code error;
    fs::create_directories(out / "samples", error);
    if (error)
        refuseOut(fmt::format("cannot make '{}': {}", (out / "samples").string(), error.message()));
    const fs::path manifest = out / "manifest.json";
    if (fs::exists(manifest, error))
        return;
    const std::string text = manifestJson(sweep, base).dump(2) + "\n";
    try {
        writeFileAtomically(manifest, text);
    } catch (const Error&) {
        // Another shard's run, started at the same moment, wrote it first.
        if (!fs::exists(manifest, error) || readFileBytes(manifest) != text)
            throw;
    }
}

namespace {

// Why frame `frame` of sample `index` is not done ("" when it is).
std::string frameNotDone(const fs::path& out, int index, const Sweep& sweep, const SweepSample& sample, int frame,
                         const std::string& camera)
{
    const std::vector<fs::path> files = frameFiles(out, index, sweep, frame, camera);
    const fs::path& jsonPath = files.back();
    std::error_code error;
    for (const fs::path& f : files)
        if (!fs::is_regular_file(f, error))
            return fmt::format("{} is missing", f.filename().string());
    const auto named = [](const fs::path& f, const std::string& problem) {
        return fmt::format("{} is {}", f.filename().string(), problem);
    };
    Json json;
    try {
        json = Json::parse(readFileBytes(jsonPath));
    } catch (const std::exception& e) {
        // nlohmann's words without its "[json.exception.parse_error.101] ".
        const std::string_view why = e.what();
        const std::size_t tag = why.starts_with("[json.") ? why.find("] ") : std::string_view::npos;
        return named(jsonPath, fmt::format("not JSON (cut short or emptied?): {}",
                                           tag == std::string_view::npos ? why : why.substr(tag + 2)));
    }
    Json varied = Json::object();
    for (std::size_t k = 0; k < sweep.vary.size(); ++k)
        varied[sweep.vary[k].key] = sweptValueJson(sweep.vary[k], sample.values[k]);
    const auto holds = [&json](const char* key, const Json& value) { return json.contains(key) && json[key] == value; };
    const double time_s = sweep.clip ? sweep.clip->frameTime_s(sample.time_s, frame) : sample.time_s;
    if (!json.is_object() || !holds("sample", index) || !holds("size", Json::array({sweep.size.x, sweep.size.y})) ||
        !holds("time_s", time_s) || !holds("varied", varied) || (sweep.clip && !holds("frame", frame)))
        return named(jsonPath, "not this sweep's sample (its index, frame, size, time or varied values are not the "
                               "manifest's)");
    if (const std::string p = pngProblem(files[0], sweep.size); !p.empty())
        return named(files[0], p);
    if (!sweep.labels)
        return {};
    const int w = sweep.size.x, h = sweep.size.y;
    const std::array<std::string, 5> arrays = {
        npyProblem(files[1], "<f4", {h, w}, 4), npyProblem(files[2], "<f4", {h, w, 3}, 4),
        npyProblem(files[3], "<u2", {h, w}, 2), npyProblem(files[4], "<u2", {h, w}, 2),
        npyProblem(files[5], "<f4", {h, w}, 4)};
    for (std::size_t i = 0; i < arrays.size(); ++i)
        if (!arrays[i].empty())
            return named(files[i + 1], arrays[i]);
    if (const std::string p = pngProblem(files[6], sweep.size); !p.empty())
        return named(files[6], p);
    const int objects = json.contains("objects") && json["objects"].is_array() ? int(json["objects"].size()) : 0;
    if (const std::string p = npyProblem(files[7], "|u1", {objects, h, w}, 1); !p.empty())
        return named(files[7], p);
    if (!sweep.clip)
        return {};
    // A clip frame's flow: its two files, just before the JSON (frameFiles()).
    const std::size_t flowFile = files.size() - 3;
    const std::array<std::string, 2> flow = {npyProblem(files[flowFile], "<f4", {h, w, 2}, 4),
                                             npyProblem(files[flowFile + 1], "|u1", {h, w}, 1)};
    for (std::size_t i = 0; i < flow.size(); ++i)
        if (!flow[i].empty())
            return named(files[flowFile + i], flow[i]);
    return {};
}

} // namespace

std::string sampleNotDone(const fs::path& out, int index, const Sweep& sweep, const SweepSample& sample)
{
    for (int frame = 0; frame < framesOf(sweep); ++frame)
        for (const std::string& camera : frameCameras(sample.scene))
            if (std::string why = frameNotDone(out, index, sweep, sample, frame, camera); !why.empty())
                return why;
    return {};
}

void removeSample(const fs::path& out, int index, const Sweep& sweep, const std::vector<std::string>& cameras)
{
    std::error_code error;
    // The JSONs first: from then on the sample is not done, whatever is left.
    Sweep everything = sweep;
    everything.labels = true;
    for (int frame = 0; frame < framesOf(sweep); ++frame)
        for (const std::string& camera : cameras)
            fs::remove(frameFiles(out, index, everything, frame, camera).back(), error);
    for (int frame = 0; frame < framesOf(sweep); ++frame)
        for (const std::string& camera : cameras)
            for (const fs::path& f : frameFiles(out, index, everything, frame, camera))
                fs::remove(f, error);
    // The temporary files of its writes (swell/dataset/atomic_file.h:
    // ".NAME.*.tmp"; a clip's frames ".NNNNNN_FFFFF.*.tmp").
    const std::string still = fmt::format(".{:06d}.", index), clip = fmt::format(".{:06d}_", index);
    for (const fs::directory_entry& e : fs::directory_iterator(out / "samples", error)) {
        const std::string name = e.path().filename().string();
        if ((name.starts_with(still) || name.starts_with(clip)) && name.ends_with(".tmp"))
            fs::remove(e.path(), error);
    }
}

void removeOrphanedTemporaries(const fs::path& out)
{
    std::error_code error;
    for (const fs::directory_entry& e : fs::directory_iterator(out, error)) {
        const std::string name = e.path().filename().string();
        for (std::string_view target : {".manifest.json.", ".coco.json."}) {
            if (!name.starts_with(target) || !name.ends_with(".tmp"))
                continue;
            // ".manifest.json.PID-N.tmp": gone when no process has that id.
            const std::string_view rest = std::string_view(name).substr(target.size());
            int pid = 0;
            const auto [end, failed] = std::from_chars(rest.data(), rest.data() + rest.size(), pid);
            if (failed == std::errc() && pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH)
                fs::remove(e.path(), error);
        }
    }
}

Json sweptValueJson(const SweepKey& key, const ParameterValue& v)
{
    if (const Parameter* p = sweptParameter(key.key); p && p->kind == ParameterKind::Choice)
        return std::string(p->choices[std::size_t(std::get<std::int64_t>(v))]);
    if (const auto* d = std::get_if<double>(&v))
        return *d;
    if (const auto* i = std::get_if<std::int64_t>(&v))
        return *i;
    if (const auto* b = std::get_if<bool>(&v))
        return *b;
    if (const auto* v2 = std::get_if<glm::dvec2>(&v))
        return Json::array({v2->x, v2->y});
    const glm::dvec3 v3 = std::get<glm::dvec3>(v);
    return Json::array({v3.x, v3.y, v3.z});
}

} // namespace swell::app
