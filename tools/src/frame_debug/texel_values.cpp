#include "frame_debug/texel_values.h"

#include <zlib.h>

#include <cstring>

namespace kiln::tools {
namespace {

std::string Base64(const std::vector<uint8_t>& in) {
    static const char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((in.size() + 2) / 3 * 4);
    for (size_t i = 0; i < in.size(); i += 3) {
        const uint32_t n = uint32_t(in[i]) << 16 | (i + 1 < in.size() ? in[i + 1] << 8 : 0) |
                           (i + 2 < in.size() ? in[i + 2] : 0);
        out += kDigits[(n >> 18) & 63];
        out += kDigits[(n >> 12) & 63];
        out += i + 1 < in.size() ? kDigits[(n >> 6) & 63] : '=';
        out += i + 2 < in.size() ? kDigits[n & 63] : '=';
    }
    return out;
}

}  // namespace

Result<std::string> TexelValuesScript(const std::string& key, const runtime::DebugImage& image) {
    const bool single = !image.single.empty();
    const size_t texels = size_t(image.width) * image.height;
    const size_t values = single ? image.single.size() : image.half.size();
    if (values == 0 || texels == 0 || values != texels * (single ? 1 : 4) ||
        image.rgba8.size() != texels * 4) {
        return std::string();
    }
    std::vector<uint8_t> raw(values * (single ? 4 : 2) + image.rgba8.size());
    std::memcpy(raw.data(),
                single ? static_cast<const void*>(image.single.data()) : image.half.data(),
                values * (single ? 4 : 2));
    std::memcpy(raw.data() + values * (single ? 4 : 2), image.rgba8.data(), image.rgba8.size());
    uLongf size = compressBound(uLong(raw.size()));
    std::vector<uint8_t> packed(size);
    if (compress2(packed.data(), &size, raw.data(), uLong(raw.size()), 6) != Z_OK) {
        return Error{DiagCode::kCannotWriteFile,
                     "cannot compress the texel values of '" + key + "'"};
    }
    packed.resize(size);
    return "kilnValues(\"" + key + "\",{w:" + std::to_string(image.width) +
           ",h:" + std::to_string(image.height) + ",c:" + std::string(single ? "1" : "4") +
           ",t:\"" + (single ? "f32" : "f16") + "\",z:\"" + Base64(packed) + "\"});\n";
}

// Values print with 4 significant digits (the halves hold about 3.3); a depth of exactly 1 is
// the cleared buffer.
const char* const kTexelReadoutScript = R"(const texelData={};
window.kilnValues=(key,v)=>{if(texelData[key])texelData[key].resolve(v);};
function halfToFloat(h){const s=h&0x8000?-1:1,e=(h>>10)&31,m=h&1023;
return e===0?s*m*Math.pow(2,-24):e===31?(m?NaN:s*Infinity):s*(1+m/1024)*Math.pow(2,e-15);}
async function inflate(v){const bin=Uint8Array.from(atob(v.z),c=>c.charCodeAt(0));
const buf=await new Response(new Blob([bin]).stream().pipeThrough(new DecompressionStream('deflate'))).arrayBuffer();
const n=v.w*v.h*v.c,size=v.t==='f32'?4:2;
return{w:v.w,h:v.h,c:v.c,values:v.t==='f32'?new Float32Array(buf.slice(0,n*4)):new Uint16Array(buf.slice(0,n*2)),
half:v.t!=='f32',display:new Uint8Array(buf,n*size,v.w*v.h*4)};}
function texels(img){const key=img.dataset.values;if(!key)return Promise.resolve(null);
if(!texelData[key]){let resolve;const p=new Promise(r=>resolve=r);texelData[key]={resolve,p:p.then(inflate)};
const s=document.createElement('script');s.src=key;s.onerror=()=>texelData[key].resolve(null);document.head.appendChild(s);}
return texelData[key].p.catch(()=>null);}
function number(v){return Number.isFinite(v)?(+v.toPrecision(4)).toString():String(v);}
async function readout(img,x,y){const where='texel '+x+', '+y+' of '+img.alt;const t=await texels(img);
if(!t||x<0||y<0||x>=t.w||y>=t.h)return where;const i=y*t.w+x;
const get=k=>t.half?halfToFloat(t.values[i*t.c+k]):t.values[i*t.c+k];
const d=[0,1,2].map(k=>t.display[i*4+k]).join(' ');
if(t.c===1){const v=get(0);return where+': '+(img.dataset.depth?'depth '+number(v)+(v===1?' (cleared)':''):'value '+number(v))+'; shown '+d;}
return where+': linear '+[0,1,2,3].map(k=>number(get(k))).join(' ')+'; shown '+d;})";

}  // namespace kiln::tools
