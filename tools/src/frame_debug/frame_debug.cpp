// WriteFrameDebug: a captured frame (kiln/runtime/frame_capture.h) as files a person opens in a
// browser. The page lists every pass with its steps and every step's images in static HTML, so
// it reads without script too; its script shows one step at a time (the list, the buttons, the
// arrow keys, or a #step-N link), and, once the page has loaded, counts the images that loaded
// into <body data-images-loaded> and those shown at their target's aspect ratio into
// data-images-in-proportion, which the headless-browser test reads. Steps are numbered from 1,
// one way everywhere: the list, the titles, the counter, the links and frame.json.
#include "kiln/tools/frame_debug.h"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include <nlohmann/json.hpp>

#include "frame_debug/texel_values.h"
#include "kiln/base/files.h"
#include "kiln/runtime/color.h"

namespace kiln::tools {

using runtime::DebugImage;
using runtime::DebugStep;
using runtime::FrameCapture;
using runtime::WritePng;
namespace {

namespace fs = std::filesystem;

std::string Escape(const std::string& s) {
    std::string out;
    for (char ch : s) {
        switch (ch) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += ch;
        }
    }
    return out;
}

// "gbuffer2 (normal)" -> "gbuffer2-normal": a file-name part.
std::string Slug(const std::string& s) {
    std::string out;
    for (char ch : s) {
        const bool alnum = (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9');
        if (alnum || (ch >= 'A' && ch <= 'Z')) {
            out += char(alnum ? ch : ch - 'A' + 'a');
        } else if (!out.empty() && out.back() != '-') {
            out += '-';
        }
    }
    while (!out.empty() && out.back() == '-') {
        out.pop_back();
    }
    return out.empty() ? "target" : out;
}

// A draw's object label with the material file's path relative to the scene's folder:
// "../materials/Lambert.material on node 'Lambert'" rather than an absolute path.
std::string RelativeLabel(const std::string& object, const std::string& scene) {
    const size_t on = object.find(" on ");
    const std::string name = object.substr(0, on);
    if (name.find('/') == std::string::npos) {
        return object;  // "glTF material 'x'", a name without a folder
    }
    std::error_code ec;
    const fs::path base = fs::absolute(fs::path(scene).parent_path(), ec).lexically_normal();
    const fs::path file = fs::absolute(name, ec).lexically_normal();
    const fs::path relative = file.lexically_relative(base);
    if (ec || relative.empty()) {
        return object;
    }
    return relative.string() + (on == std::string::npos ? "" : object.substr(on));
}

std::string ImageFile(size_t step, const DebugImage& image) {
    char number[24];
    std::snprintf(number, sizeof number, "%04zu", step);
    return std::string("steps/") + number + "-" + Slug(image.target) + ".png";
}

// The script with the image's texel values (frame_debug/texel_values.h).
std::string ValuesFile(size_t step, const DebugImage& image) {
    std::string png = ImageFile(step, image);
    return png.substr(0, png.size() - 4) + ".js";
}

// What a step did, without its number (which the list and the heading give).
std::string StepTitle(const DebugStep& s, const std::string& scene) {
    if (!s.copy.empty()) {
        return "copy " + s.copy;
    }
    if (s.draw < 0) {
        return "clear";
    }
    std::string t = "draw " + s.shader + " / " + s.shader_pass;
    if (!s.object.empty()) {
        t += " on " + RelativeLabel(s.object, scene);
    }
    if (!s.light.empty()) {
        t += ", " + s.light;
    }
    return t;
}

// The file of step `step`'s thumbnail of a texture.
std::string ThumbnailFile(size_t step, const runtime::DebugTexture& t) {
    char number[24];
    std::snprintf(number, sizeof number, "%04zu", step);
    return std::string("textures/") + number + "-" + Slug(t.name) + ".png";
}

// "0.5, 1, 2.25": a value as the uniform block holds it.
std::string Floats(const std::vector<float>& v) {
    std::string out;
    char buf[32];
    for (float f : v) {
        std::snprintf(buf, sizeof buf, "%g", double(f));
        out += (out.empty() ? "" : ", ") + std::string(buf);
    }
    return out;
}

// "mesh 'sphere', primitive 0: 2145 vertices, 12288 indices (4096 triangles)".
std::string MeshLine(const DebugStep& s) {
    if (s.mesh.empty()) {
        return "";
    }
    const uint32_t triangles = s.index_count / 3;
    return s.mesh + ": " + std::to_string(s.vertex_count) + " vertices, " +
           std::to_string(s.index_count) + " indices (" + std::to_string(triangles) +
           (triangles == 1 ? " triangle)" : " triangles)");
}

nlohmann::json Record(size_t n, const DebugStep& s, const std::string& scene) {
    nlohmann::json j = {{"step", n},
                        {"pass", s.pass},
                        {"draw", s.draw},
                        {"shader", s.shader},
                        {"shader_pass", s.shader_pass},
                        {"light_mode", s.light_mode},
                        {"keywords", s.keywords},
                        {"state", s.state},
                        {"light", s.light},
                        {"object", RelativeLabel(s.object, scene)},
                        {"copy", s.copy}};
    j["gpu_ms"] = s.gpu_ms >= 0 ? nlohmann::json(s.gpu_ms) : nlohmann::json(nullptr);
    nlohmann::json images = nlohmann::json::array();
    for (const DebugImage& image : s.images) {
        images.push_back({{"target", image.target}, {"file", ImageFile(n, image)}});
    }
    j["images"] = images;
    if (s.draw >= 0) {
        j["mesh"] = s.mesh;
        j["vertices"] = s.vertex_count;
        j["indices"] = s.index_count;
        nlohmann::json textures = nlohmann::json::array();
        for (const runtime::DebugTexture& t : s.textures) {
            textures.push_back(
                {{"name", t.name},
                 {"source", t.source},
                 {"width", t.width},
                 {"height", t.height},
                 {"format", t.format},
                 {"thumbnail", t.thumbnail.rgba8.empty() ? nlohmann::json(nullptr)
                                                         : nlohmann::json(ThumbnailFile(n, t))}});
        }
        j["textures"] = textures;
        nlohmann::json values = nlohmann::json::object();
        for (const auto& [name, v] : s.values) {
            values[name] = v;
        }
        j["values"] = values;
    }
    return j;
}

constexpr const char* kStyle = R"(body{font:14px system-ui,sans-serif;margin:0;display:flex}
h1{font-size:1.2em;word-break:break-all}
nav{width:28em;height:100vh;overflow:auto;padding:.5em 1em;border-right:1px solid #ccc}
main{flex:1;padding:.5em 1em}h2{font-size:1em;margin:.8em 0 .2em}
nav ol{margin:0;padding-left:1.2em}nav a{color:#036;text-decoration:none}
nav a.current{font-weight:bold}table{border-collapse:collapse;margin:.4em 0}
td{padding:1px 8px;vertical-align:top}td:first-child{color:#666}
figure{display:inline-block;margin:0 1em 1em 0;max-width:48vw}
img{border:1px solid #999;max-width:100%;height:auto;image-rendering:pixelated}
h3{font-size:.95em;margin:.6em 0 .2em}img.thumb{width:64px;height:auto;max-height:64px;
object-fit:contain;background:#eee}details.values td:last-child{font-family:monospace}
nav ol{list-style:none;padding-left:0}.n{color:#666;display:inline-block;min-width:2.5em}
.hidden{display:none})";

constexpr const char* kScript = R"(const steps=[...document.querySelectorAll('section.step')];
const links=[...document.querySelectorAll('nav a[data-step]')];let current=0;
function show(i,keepHash){current=Math.max(0,Math.min(steps.length-1,i));
steps.forEach((s,k)=>s.classList.toggle('hidden',k!==current));
links.forEach((a,k)=>a.classList.toggle('current',k===current));
document.body.dataset.current=current+1;
document.getElementById('position').textContent='step '+(current+1)+' of '+steps.length;
if(!keepHash&&location.hash!=='#step-'+(current+1))history.replaceState(null,'','#step-'+(current+1));}
function fromHash(){const m=/^#step-([0-9]+)$/.exec(location.hash);
if(m&&+m[1]>=1&&+m[1]<=steps.length){show(+m[1]-1,true);return true;}return false;}
window.addEventListener('hashchange',fromHash);
links.forEach((a,k)=>a.addEventListener('click',e=>{e.preventDefault();show(k);}));
document.getElementById('prev').onclick=()=>show(current-1);
document.getElementById('next').onclick=()=>show(current+1);
document.addEventListener('keydown',e=>{if(e.key==='ArrowDown'||e.key==='ArrowRight')show(current+1);
if(e.key==='ArrowUp'||e.key==='ArrowLeft')show(current-1);});
window.addEventListener('load',()=>{const imgs=[...document.images];
const ok=imgs.filter(i=>i.complete&&i.naturalWidth>0).length;
document.body.dataset.imagesLoaded=ok;
const shown=current;steps.forEach(s=>s.classList.remove('hidden'));
const inProportion=imgs.filter(i=>{const w=i.clientWidth,h=i.clientHeight;
const r=i.naturalWidth/i.naturalHeight;return i.naturalWidth>0&&h>0&&Math.abs(w/h-r)<0.02*r+1/h;});
document.body.dataset.imagesInProportion=inProportion.length;
document.body.dataset.imagesOutOfProportion=imgs.filter(i=>!inProportion.includes(i))
.map(i=>i.getAttribute('src')+' '+i.clientWidth+'x'+i.clientHeight).join(';');show(shown,true);
document.getElementById('status').textContent=ok+' of '+imgs.length+' images loaded';});
const targets=[...document.querySelectorAll('img.target')];
function zoom(z){targets.forEach(i=>{
i.style.width=z==='fit'?'':(i.naturalWidth*+z)+'px';i.style.maxWidth=z==='fit'?'':'none';
i.closest('figure').style.maxWidth=z==='fit'?'':'none';});document.body.dataset.zoom=z;
document.getElementById('zoom').value=z;}
document.getElementById('zoom').onchange=e=>zoom(e.target.value);
window.addEventListener('load',()=>{const z=new URLSearchParams(location.search).get('zoom');
if(['1','2','4'].includes(z)){zoom(z);const shown=current;steps.forEach(s=>s.classList.remove('hidden'));
document.body.dataset.zoomedOk=targets.filter(i=>i.clientWidth===i.naturalWidth*+z).length;
show(shown,true);}});
let moves=0;const pixel=document.getElementById('pixel');
targets.forEach(i=>i.addEventListener('mousemove',e=>{const r=i.getBoundingClientRect();
const x=Math.floor((e.clientX-r.left-i.clientLeft)/i.clientWidth*i.naturalWidth);
const y=Math.floor((e.clientY-r.top-i.clientTop)/i.clientHeight*i.naturalHeight);
const n=++moves;pixel.textContent='texel '+x+', '+y+' of '+i.alt;
readout(i,x,y).then(t=>{if(n===moves)pixel.textContent=t;});}));
window.addEventListener('load',()=>{const m=/^([0-9]+),([0-9]+)$/.exec(new URLSearchParams(location.search).get('probe')||'');
if(!m)return;const shown=[...steps[current].querySelectorAll('img.target')];
Promise.all(shown.map(i=>readout(i,+m[1],+m[2]).then(t=>{i.dataset.readout=t;})))
.then(()=>{document.body.dataset.probed=shown.length;});});
if(!fromHash())show(steps.length-1,true);)";

// kiln render --watch: the page asks for live.js every second (a script element, which a page
// opened from a file may load) and reloads itself when it names another frame than its own.
std::string LiveScript(const std::string& stamp) {
    return "(function(){const mine='" + stamp +
           "';setInterval(function(){const s=document.createElement('script');"
           "s.src='live.js?'+Date.now();s.onload=s.onerror=function(){s.remove();"
           "if(window.kilnFrame&&window.kilnFrame!==mine)location.reload();};"
           "document.head.appendChild(s);},1000);})();\n";
}

std::string Page(const FrameCapture& capture, const std::string& live_stamp) {
    size_t image_count = 0;  // the targets' images and the textures' thumbnails
    for (const DebugStep& s : capture.steps) {
        image_count += s.images.size();
        for (const runtime::DebugTexture& t : s.textures) {
            image_count += t.thumbnail.rgba8.empty() ? 0 : 1;
        }
    }
    std::string h = "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>" +
                    Escape("Kiln frame debugger: " + capture.scene) + "</title>\n<style>" + kStyle +
                    "</style></head>\n";
    h += "<body data-steps=\"" + std::to_string(capture.steps.size()) + "\" data-images=\"" +
         std::to_string(image_count) + "\">\n<nav>\n<h1>" + Escape(capture.scene) + "</h1>\n<p>" +
         Escape(capture.path) + " path, " + std::to_string(capture.width) + "x" +
         std::to_string(capture.height) + ", " + std::to_string(capture.steps.size()) +
         " steps</p>\n<p><button id=\"prev\">previous</button> <span id=\"position\"></span> "
         "<button id=\"next\">next</button></p>\n<p>zoom <select id=\"zoom\"><option>fit</option>"
         "<option value=\"1\">1x</option><option value=\"2\">2x</option><option "
         "value=\"4\">4x</option></select> (square texels)</p>\n<p id=\"pixel\">the texel under "
         "the cursor, with its values</p>\n<p id=\"status\"></p>\n";
    std::string open_pass;
    for (size_t n = 0; n < capture.steps.size(); ++n) {
        const DebugStep& s = capture.steps[n];
        if (n == 0 || s.pass != capture.steps[n - 1].pass) {
            if (n > 0) {
                h += "</ol></div>\n";
            }
            h += "<div class=\"pass\" data-pass=\"" + Escape(s.pass) + "\"><h2>Pass " +
                 Escape(s.pass) + "</h2><ol>\n";
        }
        const std::string number = std::to_string(n + 1);
        h += "<li><a href=\"#step-" + number + "\" data-step=\"" + number +
             "\"><span class=\"n\">" + number + "</span>" + Escape(StepTitle(s, capture.scene)) +
             "</a></li>\n";
    }
    if (!capture.steps.empty()) {
        h += "</ol></div>\n";
    }
    h += "</nav>\n<main>\n";
    for (size_t n = 0; n < capture.steps.size(); ++n) {
        const DebugStep& s = capture.steps[n];
        const std::string number = std::to_string(n + 1);
        h += "<section class=\"step\" id=\"step-" + number + "\" data-pass=\"" + Escape(s.pass) +
             "\">\n<h2>Step " + number + ", pass " + Escape(s.pass) + ": " +
             Escape(StepTitle(s, capture.scene)) + "</h2>\n<table>\n";
        auto row = [&](const char* label, const std::string& value) {
            if (!value.empty()) {
                h += "<tr><td>" + std::string(label) + "</td><td>" + Escape(value) + "</td></tr>\n";
            }
        };
        row("shader", s.shader);
        row("pass", s.shader_pass);
        row("LightMode", s.light_mode);
        row("keywords", s.draw >= 0 && s.keywords.empty() ? "(none)" : s.keywords);
        row("render state", s.state);
        row("light", s.light);
        row("object", RelativeLabel(s.object, capture.scene));
        row("mesh", MeshLine(s));
        if (s.draw >= 0) {
            char ms[32];
            std::snprintf(ms, sizeof ms, "%.3f ms", s.gpu_ms);
            row("GPU time", s.gpu_ms >= 0 ? std::string(ms) : "not measured (no timestamps)");
        }
        h += "</table>\n";
        if (!s.textures.empty()) {
            h += "<h3>Textures</h3>\n<table class=\"textures\">\n";
            for (const runtime::DebugTexture& t : s.textures) {
                std::string thumb;
                if (!t.thumbnail.rgba8.empty()) {
                    thumb = "<img class=\"thumb\" src=\"" + ThumbnailFile(n + 1, t) + "\" alt=\"" +
                            Escape(t.name) + "\" width=\"" + std::to_string(t.thumbnail.width) +
                            "\" height=\"" + std::to_string(t.thumbnail.height) + "\">";
                }
                h += "<tr><td>" + Escape(t.name) + "</td><td>" + thumb + "</td><td>" +
                     Escape(t.source) + ", " + std::to_string(t.width) + "x" +
                     std::to_string(t.height) +
                     (t.format.empty() ? std::string() : ", " + Escape(t.format)) + "</td></tr>\n";
            }
            h += "</table>\n";
        }
        if (!s.values.empty()) {
            h += "<details class=\"values\"><summary>Uniform values (" +
                 std::to_string(s.values.size()) + ")</summary>\n<table>\n";
            for (const auto& [name, v] : s.values) {
                h += "<tr><td>" + Escape(name) + "</td><td>" + Escape(Floats(v)) + "</td></tr>\n";
            }
            h += "</table></details>\n";
        }
        h += "<div class=\"images\">\n";
        for (const DebugImage& image : s.images) {
            const std::string alt = image.target + " after step " + number;
            const std::string file = ImageFile(n + 1, image);
            // Click: the image at its full size, in a tab of its own.
            const std::string values = image.half.empty() && image.single.empty()
                                           ? std::string()
                                           : " data-values=\"" + ValuesFile(n + 1, image) + "\"" +
                                                 (image.depth ? " data-depth=\"1\"" : "");
            h += "<figure><a href=\"" + file + "\" target=\"_blank\"><img class=\"target\" src=\"" +
                 file + "\"" + values + " alt=\"" + Escape(alt) + "\" width=\"" +
                 std::to_string(image.width) + "\" height=\"" + std::to_string(image.height) +
                 "\"></a><figcaption>" + Escape(image.target) + " (" + std::to_string(image.width) +
                 "x" + std::to_string(image.height) + ")</figcaption></figure>\n";
        }
        h += "</div>\n</section>\n";
    }
    h += "</main>\n<script>\n" + std::string(kTexelReadoutScript) + "\n" + std::string(kScript) +
         "\n" + (live_stamp.empty() ? std::string() : LiveScript(live_stamp)) +
         "</script>\n</body></html>\n";
    return h;
}

// DIR/name as a folder Kiln fills: a symbolic link planted there (as steps/, frame.json,
// index.html or an image) is replaced, never written through, so it cannot aim a write at
// another file.
Status MakeFolder(const std::string& dir, const char* name) {
    std::error_code ec;
    const fs::path folder = fs::path(dir) / name;
    if (fs::is_symlink(fs::symlink_status(folder, ec)))
        fs::remove(folder, ec);
    fs::create_directories(folder, ec);
    if (ec || !fs::is_directory(fs::symlink_status(folder, ec))) {
        return Error{
            DiagCode::kCannotWriteFile,
            dir + ": cannot create the frame-debug folder" +
                (ec ? ": " + ec.message() : ": " + std::string(name) + " is not a folder")};
    }
    return {};
}

}  // namespace

Status WriteFrameDebug(const std::string& dir,
                       const FrameCapture& capture,
                       const std::string& live_stamp) {
    for (const char* folder : {"steps", "textures"}) {
        if (Status e = MakeFolder(dir, folder); !e.ok()) {
            return e;
        }
    }
    const base::WriteOptions replace_links{.follow_symlinks = false};
    nlohmann::json steps = nlohmann::json::array();
    for (size_t n = 0; n < capture.steps.size(); ++n) {
        for (const DebugImage& image : capture.steps[n].images) {
            if (Status e = WritePng((fs::path(dir) / ImageFile(n + 1, image)).string(), image.width,
                                    image.height, image.rgba8, replace_links);
                !e.ok()) {
                return e;
            }
            const std::string key = ValuesFile(n + 1, image);
            Result<std::string> script = TexelValuesScript(key, image);
            if (!script) {
                return script.error();
            }
            if (script.value().empty()) {
                continue;
            }
            if (Status e = base::WriteFileAtomically((fs::path(dir) / key).string(), script.value(),
                                                     replace_links);
                !e.ok()) {
                return e;
            }
        }
        for (const runtime::DebugTexture& t : capture.steps[n].textures) {
            if (t.thumbnail.rgba8.empty()) {
                continue;
            }
            if (Status e =
                    WritePng((fs::path(dir) / ThumbnailFile(n + 1, t)).string(), t.thumbnail.width,
                             t.thumbnail.height, t.thumbnail.rgba8, replace_links);
                !e.ok()) {
                return e;
            }
        }
        steps.push_back(Record(n + 1, capture.steps[n], capture.scene));
    }
    const nlohmann::json frame = {{"scene", capture.scene},
                                  {"path", capture.path},
                                  {"width", capture.width},
                                  {"height", capture.height},
                                  {"steps", steps}};
    if (Status e = base::WriteFileAtomically((fs::path(dir) / "frame.json").string(),
                                             frame.dump(1) + "\n", replace_links);
        !e.ok()) {
        return e;
    }
    if (Status e = base::WriteFileAtomically((fs::path(dir) / "index.html").string(),
                                             Page(capture, live_stamp), replace_links);
        !e.ok() || live_stamp.empty()) {
        return e;
    }
    return base::WriteFileAtomically((fs::path(dir) / "live.js").string(),
                                     "window.kilnFrame='" + live_stamp + "';\n", replace_links);
}

}  // namespace kiln::tools
