#line 1 "a.shader"
struct V { float4 p : POSITION; };
float gone(float x) { return x; } # x;
  #pragma fragment frag
float4 kept = 1;
float4 vert(V v) : SV_POSITION { return v.p * kept; }
float onlyFrag() {
#line 40 "b.cginc"
 return 3; } float4 frag() : SV_Target { return onlyFrag(); }
