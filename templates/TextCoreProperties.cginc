// TextCoreProperties.cginc: the older name of TextCore_Properties.cginc (same uniforms).
#include "TextCore_Properties.cginc"
