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
  rxy = hx .* hx + hy .* hy;
  inv = 1 ./ sqrt (rxy + hz .* hz);
  hz .*= inv;
  hz(hz > 1) = 1;
  th = acos (hz);
  sth = sqrt (rxy) .* inv;               # sin theta_h
  r = 1 ./ sqrt (rxy);                   # cos/sin phi_h = hx/|hxy|, hy/|hxy|
  cph = hx .* r;
  sph = hy .* r;
  flat = rxy == 0;                       # h along z: phi_h is arbitrary
  if (any (flat))
    cph(flat) = 1;
    sph(flat) = 0;
  endif
  ## rotate wi about z by -phi_h, then about y by -theta_h
  x1 = wi(:,1) .* cph + wi(:,2) .* sph;
  y1 = wi(:,2) .* cph - wi(:,1) .* sph;
  x2 = x1 .* hz - wi(:,3) .* sth;
  z2 = x1 .* sth + wi(:,3) .* hz;
  z2(z2 > 1) = 1;
  z2(z2 < -1) = -1;
  td = acos (z2);
  pd = atan2 (y1, x2);
  pd += pi * (pd < 0);
endfunction
