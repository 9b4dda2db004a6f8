// readme_example.cpp - the README's example in C++ (include/mortarcontact.hpp): a unit square
// pressed onto a clamped one, P1, plane strain. Built and run by the test suite (example_readme_cxx)
// and, against an installed copy, by the install_consumer test.
#include <mortarcontact.hpp>

#include <cstdio>
#include <vector>

int main() {
  namespace mc = mortarcontact;
  const std::vector<double> xy{0, 0, 1, 0, 1, 1, 0, 1}, xy2{0, -1, 1, -1, 1, 0, 0, 0};
  const std::vector<mc_int> tri{0, 1, 2, 0, 2, 3};
  try {
    mc::Model m;                                      // destroyed when it goes out of scope
    m.set_mesh(1, xy, tri, 3);                        m.set_mesh(2, xy2, tri, 3);
    m.set_material(1, 1.0, 0.3);                      m.set_material(2, 1.0, 0.3);
    m.fix(1, {0, 3}, mc::Components::x);              m.fix(2, {0, 3}, mc::Components::x);  // on rollers
    m.fix(2, {0, 1}, mc::Components::y);
    m.add_pressure(1, {2, 3}, {0.1});                 // on the top edge
    m.set_contact(1, {0, 1});                         m.set_contact(2, {2, 3});
    m.solve();
    const std::vector<double> pressure = m.get_contact_pressure();
    for (std::size_t j = 0; j < pressure.size(); ++j) std::printf("p[%zu] = %g\n", j, pressure[j]);
  } catch (const mc::Error &e) {                      // e.status(), e.message()
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
