## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## The parameters of lobes shared across the colour channels (the private
## shared_lobes, lafortune_fit's "color", "shared"), called from the private
## folder: the Jacobian against central differences, the fold into
## per-channel Lafortune lobes (split) and its inverse (join), the bounds
## and the scale.  Run from the package root with
##   addpath ("inst"); test ("test/test_shared_lobes.m")

%!test
%! here = pwd ();
%! unwind_protect
%!   cd (fullfile (fileparts (which ("lafortune_eval")), "private"));
%!   rand ("state", 3);
%!   ## 2 lobes, reference channel 2 of 3; one stiff lobe, one broad
%!   p = [0.1; 0.2; 0.05; -0.9; 0.8; 200; 0.5; 0.3; -0.5; 0.6; 3; 1.2; 0];
%!   x = [rand(400, 1) * 2 - 1, rand(400, 1)];
%!   x(1,:) = [-0.5 0.5];                  # on the mirror line of the first lobe
%!   [f, J] = shared_lobes ("eval", p, 2, 3, x(:,1), x(:,2));
%!   assert (size (f), [1200 1]);
%!   assert (size (J), [1200 13]);
%!   Jn = zeros (size (J));
%!   for i = 1:numel (p)
%!     h = 1e-6 * max (1, abs (p(i)));
%!     q = p; q(i) += h; r = p; r(i) -= h;
%!     Jn(:,i) = (shared_lobes ("eval", q, 2, 3, x(:,1), x(:,2)) - shared_lobes ("eval", r, 2, 3, x(:,1), x(:,2))) / (2 * h);
%!   endfor
%!   assert (J, Jn, 1e-6 * max (abs (J(:))));
%!   ## the fold is exact: each channel's Lafortune lobes give the same values
%!   P = shared_lobes ("split", p, 2, 3);
%!   F = cell2mat (cellfun (@(q) __lafortune_lafortune_core__ (q, x(:,1), x(:,2)), P(:), "uniformoutput", false));
%!   assert (F, f, 1e-12 * max (f));
%!   assert (P{3}(5:7), [0; 0; 3]);        # amplitude 0: no lobe, exponent kept
%!   assert (shared_lobes ("join", P, 2), p, 1e-12);
%!   ## bounds: rho >= 0, 0 <= e <= 1e7, amplitudes >= 0
%!   [lb, ub] = shared_lobes ("bounds", 13, 3);
%!   assert (lb', [0 0 0 -Inf -Inf 0 0 0 -Inf -Inf 0 0 0]);
%!   assert (ub', [Inf Inf Inf Inf Inf 1e7 Inf Inf Inf Inf 1e7 Inf Inf]);
%!   ## the scale: the model of the data times s
%!   fs = shared_lobes ("eval", shared_lobes ("unscale", p, 1e6, 2, 3), 2, 3, x(:,1), x(:,2));
%!   assert (fs, 1e6 * f, 1e-9 * max (1e6 * f));
%! unwind_protect_cleanup
%!   cd (here);
%! end_unwind_protect
