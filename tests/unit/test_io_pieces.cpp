// A time directory in pieces, as a run on several ranks writes it (docs/parallel.md 7;
// io/VtpPieces.hpp, io/TimeDirectory.hpp): particles.pvtp naming particles_<k>.vtp, one
// per rank, each holding only the rank's own particles (not the ghosts after them).
// Read back whole it is the set sorted by id, bit for bit; read as shares (part of parts)
// the pieces split without overlap; VTK's parallel reader (ParaView's) sees every particle
// once; the pvd names the pvtp. A hostile or damaged pvtp (a Source outside the folder,
// a missing piece, pieces that disagree, an id held by two pieces) is an InputError
// naming the file, and a complete directory in pieces may be replaced by the next write.
#define BOOST_TEST_MODULE io_pieces
#include <boost/test/unit_test.hpp>
#include "../support/ErrorOf.hpp"
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include "io/VtpPieces.hpp"
#include "test_io_helpers.hpp"
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPPolyDataReader.h>

using namespace shizuku;
using namespace shizuku::iotest;
using shizuku::test::errorOf;

namespace {

const TimeState kState{0.25, 7, 1e-4, 1e-4, ""};

// Particle i of `whole` goes to piece i mod pieces; each piece is followed by two copies
// of its first particle standing for ghosts, which must not be written.
template <int D>
void writeInPieces(const std::string& dir, const std::string& name, const ParticleSet<D>& whole, int pieces) {
  const PieceWrite w = beginPieceWrite(dir, name);
  for (int k = 0; k < pieces; ++k) {
    ParticleSet<D> piece = whole;
    std::vector<std::uint8_t> other(whole.size());
    for (std::size_t i = 0; i < whole.size(); ++i) other[i] = int(i % std::size_t(pieces)) != k;
    piece.removeMarked(other);
    const std::size_t own = piece.size();
    piece.addCopy(0);
    piece.addCopy(0);
    writePiece<D>(w.folder, k, piece, own, kState);
  }
  finishPieceWrite<D>(w, pieces, whole, kState, nullptr);
}

template <int D>
ParticleSet<D> sortedById(ParticleSet<D> p) {
  p.sortById();
  return p;
}

template <int D>
void checkSame(const ParticleSet<D>& a, const ParticleSet<D>& b) {
  checkSameState(a, b);
  BOOST_TEST(sameBits(a.density, b.density));
  BOOST_TEST(a.id == b.id);
  BOOST_TEST(a.type == b.type);
  BOOST_TEST(a.surface == b.surface);
  BOOST_TEST(sameBits(a.mass, b.mass));
}

template <int D>
void roundTrip() {
  ScratchDir c;
  const ParticleSet<D> whole = randomSet<D>(50, true, 11 + D);
  writeInPieces<D>(c.path, "0.25", whole, 3);
  const std::string dir = c.path + "/0.25";
  BOOST_TEST(particleFileOf(dir) == dir + "/particles.pvtp");
  BOOST_TEST(!std::filesystem::exists(dir + "/particles.vtp"));

  TimeState s;
  const ParticleSet<D> back = readTimeDirectory<D>(c.path, "0.25", s);
  BOOST_TEST(s.step == 7);
  BOOST_REQUIRE(back.size() == whole.size());
  checkSame(back, sortedById(whole));

  // Shares: 2 parts of 3 pieces are pieces {0} and {1, 2}; together every particle once.
  ParticleSet<D> first = readTimeDirectory<D>(c.path, "0.25", s, 0, 2);
  const ParticleSet<D> second = readTimeDirectory<D>(c.path, "0.25", s, 1, 2);
  BOOST_TEST(first.size() == 17u);  // particles 0, 3, ..., 48
  BOOST_TEST(second.size() == 33u);
  BOOST_REQUIRE(first.append(second));
  checkSame(sortedById(first), sortedById(whole));

  // ParaView's reader of the pvtp sees every particle once.
  vtkNew<vtkXMLPPolyDataReader> r;
  r->SetFileName((dir + "/particles.pvtp").c_str());
  r->Update();
  BOOST_TEST(r->GetOutput()->GetNumberOfPoints() == vtkIdType(whole.size()));

  // Listed, in the series, and replaceable by the next write (here a serial one).
  const auto times = listTimeDirectories(c.path);
  BOOST_REQUIRE(times.size() == 1u);
  BOOST_TEST(slurp(c.path + "/particles.pvd").find("file=\"0.25/particles.pvtp\"") != std::string::npos);
  BOOST_TEST(whyNotReplaceable(dir) == "");
  writeTimeDirectory<D>(c.path, "0.25", whole, kState, false);
  BOOST_TEST(particleFileOf(dir) == dir + "/particles.vtp");
  BOOST_TEST(!std::filesystem::exists(dir + "/particles_0.vtp"));
}

// A folder holding a pvtp and its pieces, for damaging.
struct Pieces {
  ScratchDir c;
  std::string dir;
  Pieces() {
    writeInPieces<2>(c.path, "0.25", randomSet<2>(30, false, 5), 3);
    dir = c.path + "/0.25";
  }
  std::string readError() const {
    return errorOf([&] {
      TimeState s;
      readTimeDirectory<2>(c.path, "0.25", s);
    });
  }
  void replaceInPvtp(const std::string& from, const std::string& to) const {
    std::string text = slurp(dir + "/particles.pvtp");
    const std::size_t at = text.find(from);
    BOOST_REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
    std::ofstream(dir + "/particles.pvtp", std::ios::binary) << text;
  }
};

}  // namespace

BOOST_AUTO_TEST_CASE(roundTrip2D) { roundTrip<2>(); }
BOOST_AUTO_TEST_CASE(roundTrip3D) { roundTrip<3>(); }

BOOST_AUTO_TEST_CASE(sourceOutsideTheFolderIsRefused) {
  Pieces p;
  p.replaceInPvtp("Source=\"particles_0.vtp\"", "Source=\"../0/particles.vtp\"");
  CHECK_MESSAGE(p.readError(), "particles.pvtp", "piece 0 is '../0/particles.vtp'", "expected 'particles_0.vtp'");
}

BOOST_AUTO_TEST_CASE(missingPieceIsNamed) {
  Pieces p;
  std::filesystem::remove(p.dir + "/particles_2.vtp");
  CHECK_MESSAGE(p.readError(), "particles_2.vtp");
}

BOOST_AUTO_TEST_CASE(noPieceAndWrongTypeAreRefused) {
  Pieces p;
  std::string text = slurp(p.dir + "/particles.pvtp");
  for (int k = 0; k < 3; ++k) {
    const std::string piece = "    <Piece Source=\"" + pieceFileName(k) + "\"/>\n";
    text.erase(text.find(piece), piece.size());
  }
  std::ofstream(p.dir + "/particles.pvtp", std::ios::binary) << text;
  CHECK_MESSAGE(p.readError(), "particles.pvtp", "names no piece");
  p.replaceInPvtp("type=\"PPolyData\"", "type=\"PolyData\"");
  CHECK_MESSAGE(p.readError(), "particles.pvtp", "not a VTKFile of type PPolyData");
}

BOOST_AUTO_TEST_CASE(idHeldByTwoPiecesIsRefused) {
  Pieces p;
  // Piece 1 replaced by a copy of piece 0: every id of piece 0 is then held twice.
  std::filesystem::copy_file(p.dir + "/particles_0.vtp", p.dir + "/particles_1.vtp",
                             std::filesystem::copy_options::overwrite_existing);
  CHECK_MESSAGE(p.readError(), "particles.pvtp", "id");
}

BOOST_AUTO_TEST_CASE(piecesOfAnotherRunAreRefused) {
  Pieces p;
  ScratchDir other;
  ParticleSet<2> foreign = randomSet<2>(10, false, 9);
  foreign.mass *= 2;
  writeInPieces<2>(other.path, "0.25", foreign, 3);
  std::filesystem::copy_file(other.path + "/0.25/particles_2.vtp", p.dir + "/particles_2.vtp",
                             std::filesystem::copy_options::overwrite_existing);
  CHECK_MESSAGE(p.readError(), "particles_2.vtp", "mass, rho0 or spacing differ");
}

BOOST_AUTO_TEST_CASE(userFileKeepsTheDirectory) {
  Pieces p;
  std::ofstream(p.dir + "/notes.txt") << "mine";
  CHECK_MESSAGE(whyNotReplaceable(p.dir), "notes.txt");
}
