#version 330 compatibility
// Reflects the eye ray in the cube map.
uniform samplerCube uCube;
in vec3 vN;
in vec3 vMC;
void main() {
    vec3 E = normalize(vec3(gl_ModelViewMatrix * vec4(vMC, 1.)));
    vec3 R = reflect(E, normalize(vN));
    gl_FragColor = vec4(textureCube(uCube, R).rgb, 1.);
}
