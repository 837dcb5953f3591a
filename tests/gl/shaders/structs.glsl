// A struct uniform with an array of structs inside, and a plain array: names as the scenes use
// them ("u_s.items[1].weight", "u_list").
struct Item {
  vec3 colour;
  float weight;
};
struct Settings {
  int count;
  Item items[2];
};
uniform Settings u_s;
uniform float u_list[3];
out vec4 frag;
void main() {
  vec3 c = vec3(0.0);
  for (int i = 0; i < u_s.count; ++i) c += u_s.items[i].colour * u_s.items[i].weight;
  frag = vec4(c, u_list[0] + u_list[1] * 10.0 + u_list[2] * 100.0);
}
