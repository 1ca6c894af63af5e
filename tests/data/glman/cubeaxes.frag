#version 330 compatibility
// The screen in 3 columns x 2 rows; each cell looks up one axis of the cube
// map: bottom row +x -x +y, top row -y +z -z.
uniform samplerCube uCube;
in vec2 vST;
void main() {
    int col = int(floor(vST.s * 3.));
    int row = int(floor(vST.t * 2.));
    int i = clamp(col + 3 * row, 0, 5);
    vec3 dirs[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1));
    gl_FragColor = vec4(textureCube(uCube, dirs[i]).rgb, 1.);
}
