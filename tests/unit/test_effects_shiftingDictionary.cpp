// Tests of the effect registry (registerBuiltinEffects): every name builds its effect from the
// dictionary of system/sphSchemes with the documented defaults, stage and needs;
// invalid values and unknown words are InputErrors naming the keyword.
#define BOOST_TEST_MODULE effects_shiftingDictionary
#include <boost/test/unit_test.hpp>
#include "effects/ShiftingDistribution.hpp"
#include "effects/SurfaceFitting.hpp"
#include "effects/Effect.hpp"
#include "../support/ErrorOf.hpp"
#include <iostream>

using namespace shizuku;

namespace {

const char* kSchemes = R"(
shifting
{
    distribution      { type OPS; C 0.3; Rp 0.1; np 3; gradient concentration; }
    volumeCorrection  { C 0.05; }
    surfaceFitting    { C 2e-4; maxCurvature 0.3; minDistance 0.1; maxDistance 0.5;
                        curvatureFactor 0.9; sign asPrinted; }
    maxShift          0.1;
}
dps   { type DPS; C 0.1; }
empty { }
ads   { distance 0.9; C 0.5; }
xsph  { epsilon 0.3; }
badC  { C 0.6; }
badGradient { gradient corected; }
badBand { minDistance 0.7; maxDistance 0.6; }
)";

template <int D>
EffectRegistry<D> registry() {
  EffectRegistry<D> r;
  registerBuiltinEffects<D>(r);
  return r;
}

}  // namespace

BOOST_AUTO_TEST_CASE(names_stages_and_needs) {
  auto r = registry<2>();
  const Dictionary d = Dictionary::fromString(kSchemes, "sphSchemes");
  const Dictionary& sh = d.subDict("shifting");
  FlowState<2> s;
  auto dis = r.create("shifting/distribution", sh.subDict("distribution"), s);
  auto vol = r.create("shifting/volumeCorrection", sh.subDict("volumeCorrection"), s);
  auto suf = r.create("shifting/surfaceFitting", sh.subDict("surfaceFitting"), s);
  auto ads = r.create("ads", d.subDict("ads"), s);
  auto xsph = r.create("xsph", d.subDict("xsph"), s);
  BOOST_TEST(dis->name() == "shifting/distribution");
  BOOST_TEST(vol->name() == "shifting/volumeCorrection");
  BOOST_TEST(suf->name() == "shifting/surfaceFitting");
  BOOST_TEST(ads->name() == "ads");
  BOOST_TEST(xsph->name() == "xsph");
  BOOST_TEST((dis->stage() == EffectStage::shift && vol->stage() == EffectStage::shift &&
              suf->stage() == EffectStage::shift));
  BOOST_TEST((ads->stage() == EffectStage::postAdvection));
  BOOST_TEST((xsph->stage() == EffectStage::advection));
  BOOST_TEST(dis->needs().normals);
  BOOST_TEST(dis->needs().surfaceFit);  // its frame beside a dry wall (docs/method.md 6)
  BOOST_TEST((suf->needs().surfaceFit && suf->needs().normals));
  BOOST_TEST(!vol->needs().normals);
  for (auto* e : {dis.get(), vol.get(), suf.get(), ads.get(), xsph.get()})
    std::cout << e->name() << ": " << e->describe() << "\n";
  // Values read as written.
  const auto& p = dynamic_cast<ShiftingDistribution<2>&>(*dis).parameters();
  BOOST_TEST(p.C == 0.3);
  BOOST_TEST(p.Rp == 0.1);
  BOOST_TEST(p.np == 3);
  BOOST_TEST((p.gradient == DistributionParameters::Gradient::concentration));
  const auto& q = dynamic_cast<SurfaceFitting<2>&>(*suf).parameters();
  BOOST_TEST(q.curvatureFactor == 0.9);
  BOOST_TEST(!q.smoothingSign);
  BOOST_TEST(q.maxDistance == 0.5);
  // Every keyword of the entries was read (maxShift is the solver's).
  sh.markRead("maxShift");
  for (const char* k : {"distribution", "volumeCorrection", "surfaceFitting"}) BOOST_CHECK_NO_THROW(sh.subDict(k).checkAllRead());
  BOOST_CHECK_NO_THROW(d.subDict("ads").checkAllRead());
  BOOST_CHECK_NO_THROW(d.subDict("xsph").checkAllRead());
}

BOOST_AUTO_TEST_CASE(defaults) {
  auto r = registry<3>();
  const Dictionary d = Dictionary::fromString(kSchemes, "sphSchemes");
  FlowState<3> s;
  auto dis = r.create("shifting/distribution", d.subDict("empty"), s);
  const auto& p = dynamic_cast<ShiftingDistribution<3>&>(*dis).parameters();
  BOOST_TEST((p.type == DistributionParameters::Type::OPS));
  BOOST_TEST(p.C == 0.2);
  BOOST_TEST(p.Rp == 0.2);
  BOOST_TEST(p.np == 4);
  BOOST_TEST((p.gradient == DistributionParameters::Gradient::kernel));
  auto suf = r.create("shifting/surfaceFitting", d.subDict("empty"), s);
  const auto& q = dynamic_cast<SurfaceFitting<3>&>(*suf).parameters();
  BOOST_TEST(q.C == 1e-4);
  BOOST_TEST(q.maxCurvature == 0.2);
  BOOST_TEST(q.minDistance == 0.15);
  BOOST_TEST(q.maxDistance == 0.6);
  BOOST_TEST(q.curvatureFactor == 0.34);
  BOOST_TEST(q.smoothingSign);
  // Each default is listed for the log.
  bool listed = false;
  for (const auto& line : Dictionary::defaultsUsed()) listed = listed || line.find("curvatureFactor") != std::string::npos;
  BOOST_TEST(listed);
}

BOOST_AUTO_TEST_CASE(dps_reads_only_C) {
  auto r = registry<2>();
  const Dictionary d = Dictionary::fromString("dps { type DPS; C 0.1; Rp 0.2; }", "sphSchemes");
  FlowState<2> s;
  auto dis = r.create("shifting/distribution", d.subDict("dps"), s);
  BOOST_TEST((dynamic_cast<ShiftingDistribution<2>&>(*dis).parameters().type == DistributionParameters::Type::DPS));
  // Rp has no meaning for DPS: left unread, so the solver's checkAllRead reports it.
  BOOST_CHECK_THROW(d.checkAllRead(), InputError);
}

BOOST_AUTO_TEST_CASE(invalid_values) {
  auto r = registry<2>();
  const Dictionary d = Dictionary::fromString(kSchemes, "sphSchemes");
  FlowState<2> s;
  auto message = [&](const std::string& name, const char* entry) {
    return test::errorOf([&] { r.create(name, d.subDict(entry), s); });
  };
  const std::string c = message("shifting/distribution", "badC");
  BOOST_TEST(c.find("0.5") != std::string::npos, c);
  const std::string g = message("shifting/distribution", "badGradient");
  BOOST_TEST(g.find("corrected") != std::string::npos, g);  // did-you-mean
  const std::string b = message("shifting/surfaceFitting", "badBand");
  BOOST_TEST(b.find("maxDistance") != std::string::npos, b);
  std::cout << c << "\n" << g << "\n" << b << "\n";
}
