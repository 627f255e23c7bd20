#include <CGAL/Bubble_mesh_3/Geological_model_3.h>
#include <iostream>
int main() { CGAL::Bubble_mesh_3::Geological_model_3<> m; std::cout << m.number_of_regions() << "\n"; return 0; }
