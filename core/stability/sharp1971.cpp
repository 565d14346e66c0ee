#include "core/stability/motorcycle.h"

namespace mozzi::core::stability {

SharpParameters sharp1971Parameters() {
  // Sharp (1971), Appendix 3, in SI: the value_si column of
  // shared/data/motorcycle/sharp1971-parameters.csv.
  SharpParameters p;
  p.Mf = 30.6472;
  p.Mr = 217.449;
  p.Zf = -1005.3;
  p.Irx = 31.1838;
  p.Irz = 21.0694;
  p.Crxz = 1.73545;
  p.Ifx = 1.23379;
  p.Ifz = 0.441997;
  p.ify = 0.718584;
  p.iry = 1.05076;
  p.a = 0.948538;
  p.b = 0.479755;
  p.e = 0.024384;
  p.f = 0.0283464;
  p.h = 0.615696;
  p.Rf = 0.3048;
  p.Rr = 0.3048;
  p.t = 0.115824;
  p.eps = 0.4715;
  p.Cf1 = 11173.9;
  p.Cf2 = 938.575;
  p.Cr1 = 15831.2;
  p.Cr2 = 1325.57;
  p.K = 6.77909;
  p.sigma = 0.24384;
  p.trust =
      "Sharp (1971) \"standard machine\", paper Appendix 3, transcribed by a third party and converted to SI. "
      "Trust: a single transcription, not checked against the paper.";
  return p;
}

}  // namespace mozzi::core::stability
