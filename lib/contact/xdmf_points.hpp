// XDMF sidecar of a contact run's output: the body centres as a point cloud (Polyvertex), one grid per frame
// with the orientation (w, x, y, z) and velocities as attributes, read from the HDF5 file's /frames datasets
// (ParaView: open the .xmf, play; glyph by orientation). Written to xmf.tmp, then renamed.
#pragma once

#include <string>
#include <vector>

namespace suite::contact {

// nb bodies, nf frames at times t; h5: the HDF5 file the datasets are in (referred to by its base name).
void writeXdmf(const std::string& xmf, const std::string& h5, size_t nb, size_t nf,
               const std::vector<double>& t);

} // namespace suite::contact
