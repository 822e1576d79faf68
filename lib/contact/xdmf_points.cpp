// XDMF sidecar of a contact run's frames (see xdmf_points.hpp).
#include "contact/xdmf_points.hpp"

#include <cstdio>
#include <fstream>

namespace suite::contact {

namespace {
std::string baseName(const std::string& p) {
  const auto k = p.find_last_of('/');
  return k == std::string::npos ? p : p.substr(k + 1);
}

} // namespace

void writeXdmf(const std::string& xmf, const std::string& h5, size_t nb, size_t nf,
               const std::vector<double>& t) {
  const std::string tmp = xmf + ".tmp";
  std::ofstream o(tmp);
  const std::string f = baseName(h5);
  o << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n"
    << "<Grid Name=\"bodies\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  auto slab = [&](const char* ds, size_t k, size_t comps) {
    o << "  <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << nb << " " << comps << "\">\n"
      << "   <DataItem Dimensions=\"3 3\" Format=\"XML\">" << k << " 0 0 1 1 1 1 " << nb << " " << comps
      << "</DataItem>\n"
      << "   <DataItem Dimensions=\"" << nf << " " << nb << " " << comps << "\" Format=\"HDF\">" << f << ":"
      << ds << "</DataItem>\n  </DataItem>\n";
  };
  for (size_t k = 0; k < nf; ++k) {
    o << " <Grid Name=\"frame" << k << "\" GridType=\"Uniform\">\n  <Time Value=\"" << t[k] << "\"/>\n"
      << "  <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << nb << "\"/>\n"
      << "  <Geometry GeometryType=\"XYZ\">\n";
    slab("/frames/positions", k, 3);
    o << "  </Geometry>\n  <Attribute Name=\"orientation_wxyz\" AttributeType=\"Vector\" Center=\"Node\">\n";
    slab("/frames/orientations", k, 4);
    o << "  </Attribute>\n  <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n";
    slab("/frames/velocities", k, 6);
    o << "  </Attribute>\n </Grid>\n";
  }
  o << "</Grid>\n</Domain>\n</Xdmf>\n";
  o.close();
  std::rename(tmp.c_str(), xmf.c_str());
}

} // namespace suite::contact
