## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{th}, @var{td}, @var{pd}] =} merl_angles (@var{wi}, @var{wo})
## Rusinkiewicz half/difference angles of direction pairs (private), as the
## MERL reference reader computes them: h = normalize (wi + wo); the difference
## vector is wi rotated about z by -phi_h, then about y by -theta_h.
## phi_d is returned in [0, pi) (reciprocity fold).  Column vectors.
## @end deftypefn
function [th, td, pd] = merl_angles (wi, wo)
  hx = wi(:,1) + wo(:,1);
  hy = wi(:,2) + wo(:,2);
  hz = wi(:,3) + wo(:,3);
  hn = sqrt (hx .^ 2 + hy .^ 2 + hz .^ 2);
  hx ./= hn; hy ./= hn; hz ./= hn;
  hz = min (max (hz, -1), 1);
  th = acos (hz);
  sth = sqrt (hx .^ 2 + hy .^ 2);        # sin theta_h
  r = sth;
  r(r == 0) = 1;
  cph = hx ./ r;                         # cos phi_h
  sph = hy ./ r;                         # sin phi_h
  cph(sth == 0) = 1;
  ## rotate wi about z by -phi_h
  x1 = wi(:,1) .* cph + wi(:,2) .* sph;
  y1 = wi(:,2) .* cph - wi(:,1) .* sph;
  z1 = wi(:,3);
  ## then about y by -theta_h
  x2 = x1 .* hz - z1 .* sth;
  z2 = x1 .* sth + z1 .* hz;
  td = acos (min (max (z2, -1), 1));
  pd = atan2 (y1, x2);
  pd(pd < 0) += pi;
endfunction
