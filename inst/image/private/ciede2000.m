## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{de} =} ciede2000 (@var{lab1}, @var{lab2})
## CIEDE2000 colour difference (private) of the rows of @var{lab1} and
## @var{lab2} (N x 3 CIELAB), with kL = kC = kH = 1: N x 1.  The formula
## as in Sharma, Wu and Dalal (2005), "The CIEDE2000 color-difference
## formula: implementation notes, supplementary test data, and mathematical
## observations", Color Res.@: Appl.@: 30(1), eqs.@: (1) to (18), including their
## conventions for the hue angle and the mean hue where a chroma is zero and
## where the hues are 180 degrees apart.  Symmetric in its arguments.
## @end deftypefn
function de = ciede2000 (lab1, lab2)
  L1 = lab1(:,1); a1 = lab1(:,2); b1 = lab1(:,3);
  L2 = lab2(:,1); a2 = lab2(:,2); b2 = lab2(:,3);
  Cab = (sqrt (a1.*a1 + b1.*b1) + sqrt (a2.*a2 + b2.*b2)) / 2;
  c7 = pow7 (Cab);
  G = 0.5 * (1 - sqrt (c7 ./ (c7 + 25^7)));
  a1 = (1 + G) .* a1;
  a2 = (1 + G) .* a2;
  C1 = sqrt (a1.*a1 + b1.*b1);
  C2 = sqrt (a2.*a2 + b2.*b2);
  h1 = mod (atan2d (b1, a1), 360);         # atan2 (0, 0) = 0, eq. (4)
  h2 = mod (atan2d (b2, a2), 360);
  zero = C1 .* C2 == 0;

  dL = L2 - L1;
  dC = C2 - C1;
  dh = h2 - h1;
  dh(dh > 180) -= 360;
  dh(dh < -180) += 360;
  dh(zero) = 0;
  dH = 2 * sqrt (C1 .* C2) .* sind (dh / 2);

  Lm = (L1 + L2) / 2;
  Cm = (C1 + C2) / 2;
  hm = h1 + h2;
  far = ! zero & abs (h1 - h2) > 180;
  hm(far) += 360 * (1 - 2 * (hm(far) >= 360));   # +360 below 360, else -360
  hm(! zero) /= 2;

  T = 1 - 0.17 * cosd (hm - 30) + 0.24 * cosd (2 * hm) ...
      + 0.32 * cosd (3 * hm + 6) - 0.20 * cosd (4 * hm - 63);
  dtheta = (hm - 275) / 25;
  dtheta = 30 * exp (-dtheta .* dtheta);
  c7 = pow7 (Cm);
  RC = 2 * sqrt (c7 ./ (c7 + 25^7));
  SL = (Lm - 50) .* (Lm - 50);
  SL = 1 + 0.015 * SL ./ sqrt (20 + SL);
  SC = 1 + 0.045 * Cm;
  SH = 1 + 0.015 * Cm .* T;
  RT = -sind (2 * dtheta) .* RC;
  x = dL ./ SL;
  y = dC ./ SC;
  z = dH ./ SH;
  de = sqrt (x.*x + y.*y + z.*z + RT .* y .* z);
endfunction

## c^7 by products (faster than .^)
function p = pow7 (c)
  c2 = c .* c;
  p = c2 .* c2 .* c2 .* c;
endfunction
