## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{wi}, @var{wo}] =} __lafortune_slice_dirs__ (@var{ti}, @var{to}, @var{cg})
## Local directions of the pair with angles @var{ti} = angle (N, L),
## @var{to} = angle (N, V) and cos (angle (L, V)) = @var{cg} (column vectors
## or scalars): wo in the xz plane, wi at the azimuth phi with
## cos @var{cg} = cos ti cos to + sin ti sin to cos phi, cos phi clamped to
## [-1, 1] where no normal reaches the combination (the nearest reachable
## configuration).  Private: the one construction behind @code{scene_slice}
## and @code{merl_scene}.  This code is the definition; the oct-file
## __slice_dirs__ makes the same operations, compiled, when it is built (for
## real double columns TI, TO of one length, CG one or as many).
## @end deftypefn
function [wi, wo] = __lafortune_slice_dirs__ (ti, to, cg)
  if (isa (ti, "double") && isa (to, "double") && isa (cg, "double") && isreal (ti)
      && isreal (to) && isreal (cg) && ! issparse (ti) && ! issparse (to) && ! issparse (cg)
      && iscolumn (ti) && iscolumn (to) && numel (to) == numel (ti)
      && (isscalar (cg) || (iscolumn (cg) && numel (cg) == numel (ti))))
    [done, wi, wo] = __lafortune_oct_call__ ("__slice_dirs__", "__lafortune_slice_dirs__", ti, to, cg);
    if (done)
      return;
    endif
  endif
  si = sin (ti);
  ci = cos (ti);
  so = sin (to);
  co = cos (to);
  s = si .* so;
  cphi = (cg - ci .* co) ./ s;
  cphi(s <= 0) = 1;
  cphi = min (max (cphi, -1), 1);
  sphi = sqrt (1 - cphi .^ 2);
  wi = [si .* cphi, si .* sphi, ci];
  wo = [so, zeros(size (to)), co];
  wi ./= sqrt (sum (wi .^ 2, 2));
endfunction
