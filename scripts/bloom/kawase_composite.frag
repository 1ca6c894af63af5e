#version 330 compatibility

// Dual Kawase bloom, on the screen: the last upsample (half size -> full size, the
// kawase_up filter inline), times uBloomStrength, added to the HDR scene, then
// exposure tone mapping and gamma as learnopengl.glib.
uniform sampler2D SceneUnit;
uniform sampler2D BloomUnit;    // the half-size upsample
uniform float uOffset;
uniform float uBloomStrength;
uniform float uExposure;
uniform float uGamma;

in vec2 vST;

void main( )
{
    vec2 halfpixel = 0.5 / vec2( textureSize( BloomUnit, 0 ) );
    vec2 h = halfpixel * uOffset;
    vec3 sum = texture( BloomUnit, vST + vec2( -h.x * 2., 0. ) ).rgb;
    sum += texture( BloomUnit, vST + vec2( -h.x, h.y ) ).rgb * 2.;
    sum += texture( BloomUnit, vST + vec2( 0., h.y * 2. ) ).rgb;
    sum += texture( BloomUnit, vST + vec2( h.x, h.y ) ).rgb * 2.;
    sum += texture( BloomUnit, vST + vec2( h.x * 2., 0. ) ).rgb;
    sum += texture( BloomUnit, vST + vec2( h.x, -h.y ) ).rgb * 2.;
    sum += texture( BloomUnit, vST + vec2( 0., -h.y * 2. ) ).rgb;
    sum += texture( BloomUnit, vST + vec2( -h.x, -h.y ) ).rgb * 2.;
    vec3 bloom = sum / 12.;

    vec3 hdr = texture( SceneUnit, vST ).rgb + uBloomStrength * bloom;
    vec3 result = vec3( 1. ) - exp( -hdr * uExposure );
    result = pow( result, vec3( 1. / uGamma ) );
    gl_FragColor = vec4( result, 1. );
}
