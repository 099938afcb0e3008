## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {[@var{wi}, @var{wo}] =} __lafortune_merl_grid__ ()
## @deftypefnx {} {[@var{wi}, @var{wo}] =} __lafortune_merl_grid__ (@var{idx})
## Directions of every MERL bin (private), in bin order (phi_d fastest), at
## the grid points theta_h = (i/90)^2 pi/2, theta_d = j/90 pi/2,
## phi_d = k/180 pi, with phi_h = 0.  1458000 x 3 each, or only the bins
## with the (1-based) indices @var{idx}, in that order.  This code is the
## definition; the oct-file __merl_grid__ makes the same operations,
## compiled, when it is built.
## @end deftypefn
function [wi, wo] = __lafortune_merl_grid__ (idx)
  args = {};
  if (nargin >= 1)
    args = {double(idx(:))};
  endif
  [done, wi, wo] = __lafortune_oct_call__ ("__merl_grid__", "__lafortune_merl_grid__", args{:});
  if (done)
    return;
  endif
  if (nargin < 1)
    [ip, id, ih] = ndgrid (0:179, 0:89, 0:89);
    ip = ip(:); id = id(:); ih = ih(:);
  else
    k = idx(:) - 1;
    ip = mod (k, 180);
    id = mod (floor (k / 180), 90);
    ih = floor (k / 16200);
  endif
  th = (ih / 90) .^ 2 * pi / 2;
  td = id / 90 * pi / 2;
  pd = ip / 180 * pi;
  dx = sin (td) .* cos (pd);
  dy = sin (td) .* sin (pd);
  dz = cos (td);
  c = cos (th);
  s = sin (th);
  ## rotate the difference vector back: about y by +theta_h (phi_h = 0)
  wi = [dx .* c + dz .* s, dy, -dx .* s + dz .* c];
  wo = [-dx .* c + dz .* s, -dy, dx .* s + dz .* c];
endfunction
