## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{idx} =} merl_index_ref (@var{wi}, @var{wo})
## MERL bin index (1-based) of direction pairs computed with the very
## operations of the database's reference reader (private): half vector
## (wi + wo)/2 normalised, theta_h = acos, phi_h = atan2, the difference
## vector by two Rodrigues rotations (about z by -phi_h, about y by
## -theta_h) written out term by term as the reader does, then its index
## formulas.  Same inputs, same doubles, same bins, including the cases
## where rounding decides: a direction exactly on a bin edge, or h along the
## normal, where phi_h comes from atan2 of rounding residues.  merl_eval's
## method "reference" (the benchmark's peer, and the fallback when the
## oct-file __merl_nearest__ is missing); the oct-file's own copy of these
## operations places the samples its fast path cannot place with certainty.
## @end deftypefn
function idx = merl_index_ref (wi, wo)
  hx = (wi(:,1) + wo(:,1)) / 2;
  hy = (wi(:,2) + wo(:,2)) / 2;
  hz = (wi(:,3) + wo(:,3)) / 2;
  len = sqrt (hx .* hx + hy .* hy + hz .* hz);
  hx ./= len; hy ./= len; hz ./= len;
  th = acos (hz);
  ph = atan2 (hy, hx);
  ## rotate wi about n = (0, 0, 1) by -phi_h
  [tx, ty, tz] = rodrigues (wi(:,1), wi(:,2), wi(:,3), 0, 0, 1, -ph);
  ## then about b = (0, 1, 0) by -theta_h
  [dx, dy, dz] = rodrigues (tx, ty, tz, 0, 1, 0, -th);
  td = acos (dz);
  pd = atan2 (dy, dx);
  ih = zeros (size (th));
  pos = th > 0;
  t = ((th(pos) / (pi / 2.0)) * 90) * 90;
  ih(pos) = fix (sqrt (t));
  ih = min (max (ih, 0), 89);
  id = min (max (fix (td / (pi * 0.5) * 90), 0), 89);
  pd(pd < 0) += pi;
  ip = min (max (fix (pd / pi * 360 / 2), 0), 179);
  idx = ip + id * 180 + ih * 180 * 90 + 1;
endfunction

function [ox, oy, oz] = rodrigues (vx, vy, vz, ax, ay, az, ang)
  c = cos (ang);
  s = sin (ang);
  ox = vx .* c; oy = vy .* c; oz = vz .* c;
  t = ax * vx + ay * vy + az * vz;
  t = t .* (1.0 - c);
  ox += ax * t; oy += ay * t; oz += az * t;
  cx = ay * vz - az * vy;
  cy = az * vx - ax * vz;
  cz = ax * vy - ay * vx;
  ox += cx .* s; oy += cy .* s; oz += cz .* s;
endfunction
