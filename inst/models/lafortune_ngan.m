## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{model} =} lafortune_ngan (@var{rho_d}, @var{rho_s}, @var{Cxy}, @var{Cz}, @var{n})
## @deftypefnx {lafortune} {@var{model} =} lafortune_ngan (@var{file}, @var{material})
## A one-lobe Lafortune fit as Ngan, Durand and Matusik (2005) publish it,
## as this toolbox's model struct: the best-known published Lafortune fits
## of the MERL materials, a baseline for the toolbox's own.
##
## Ngan et al. normalise the lobe and share its direction and exponent
## across R, G, B:
## @example
## f = rho_d/pi + rho_s (n+2) / (2 pi max (Cxy^2, Cz^2)^(n/2)) max (Cxy (ux vx + uy vy) + Cz uz vz, 0)^n
## @end example
## which is the toolbox's lobe with C_c = k_c (Cxy, Cz), k_c = (rho_s,c
## (n+2) / (2 pi))^(1/n) / max (|Cxy|, |Cz|), e = n.  @var{rho_d} and
## @var{rho_s} are 1 x 3 (R, G, B), @var{Cxy}, @var{Cz} and @var{n} scalars.
##
## With a @var{file} (a tab-separated table with a header line
## @code{material rho_d_r rho_d_g rho_d_b rho_s_r rho_s_g rho_s_b Cxy Cz n}
## and @code{#} comments, such as @file{ngan2005/lafortune-1lobe.tsv} of the
## project's shared data), the row of @var{material}, or @code{[]} when the
## table has none.  The model's @code{name} is the material's, and
## @code{source} says where it comes from.
##
## @example
## @group
## m = lafortune_ngan ([0.015 0.0537 0.0428], [0.22 0.217 0.153], -0.591, 0.548, 76);
## lafortune_eval (m, [0 0 1], [0 0 1])    # green-metallic-paint at normal incidence
## @end group
## @end example
## @seealso{lafortune_eval, lafortune_fit, brdf_import}
## @end deftypefn
function m = lafortune_ngan (varargin)
  if (nargin == 2)
    m = from_file (varargin{:});
    return;
  elseif (nargin != 5)
    print_usage ();
  endif
  [rho_d, rho_s, Cxy, Cz, n] = varargin{:};
  ok = @(x, k) isnumeric (x) && isreal (x) && numel (x) == k && all (isfinite (x(:)));
  if (! (ok (rho_d, 3) && ok (rho_s, 3) && all (rho_d >= 0) && all (rho_s >= 0)))
    error ("lafortune:badModel",
           "lafortune_ngan: RHO_D and RHO_S must be 3 finite values >= 0 (R, G, B)");
  endif
  if (! (ok (Cxy, 1) && ok (Cz, 1) && ok (n, 1) && n > 0 && max (abs ([Cxy Cz])) > 0))
    error ("lafortune:badModel",
           "lafortune_ngan: CXY and CZ must be finite scalars, not both 0, and N a finite scalar > 0");
  endif
  k = (rho_s(:).' * (n + 2) / (2 * pi)) .^ (1 / n) / max (abs (Cxy), abs (Cz));
  m = struct ("rho_d", double (rho_d(:).'), "Cxy", Cxy * k, "Cz", Cz * k, "e", n * [1 1 1]);
endfunction

function m = from_file (file, material)
  if (! ischar (file) || ! ischar (material))
    error ("lafortune:badInput", "lafortune_ngan: FILE and MATERIAL must be strings");
  endif
  [fid, msg] = fopen (file, "r");
  if (fid < 0)
    error ("lafortune:badFile", "lafortune_ngan: cannot open %s: %s", file, msg);
  endif
  text = fread (fid, Inf, "*char")';
  fclose (fid);
  lines = strsplit (text, {"\r\n", "\n"});
  lines = lines(! cellfun (@isempty, lines) & ! strncmp (lines, "#", 1));
  want = {"material", "rho_d_r", "rho_d_g", "rho_d_b", "rho_s_r", "rho_s_g", "rho_s_b", "Cxy", "Cz", "n"};
  if (isempty (lines) || ! isequal (strtrim (strsplit (lines{1}, "\t")), want))
    error ("lafortune:badFile", "lafortune_ngan: %s must start (after # comments) with the header '%s'",
           file, strjoin (want, " "));
  endif
  m = [];
  for i = 2:numel (lines)
    f = strtrim (strsplit (lines{i}, "\t"));
    if (numel (f) != 10)
      error ("lafortune:badFile", "lafortune_ngan: %s, line '%s': expected 10 tab-separated fields",
             file, lines{i});
    endif
    if (strcmp (f{1}, material))
      v = str2double (f(2:end));
      if (any (isnan (v)))
        error ("lafortune:badFile", "lafortune_ngan: %s, material %s: a value is not a number", file, material);
      endif
      m = lafortune_ngan (v(1:3), v(4:6), v(7), v(8), v(9));
      m.name = material;
      m.source = "Ngan, Durand and Matusik 2005 (published 1-lobe Lafortune fit)";
      return;
    endif
  endfor
endfunction

%!test
%! ## the published lobe: f at the mirror direction of normal incidence is
%! ## rho_d/pi + rho_s (n+2)/(2 pi) when max (|Cxy|, |Cz|) = |Cz|
%! m = lafortune_ngan ([0.015 0.0537 0.0428], [0.22 0.217 0.153], -0.591, 0.548, 76);
%! f = lafortune_eval (m, [0 0 1], [0 0 1]);
%! n = 76; b = 0.548 / 0.591;
%! assert (f, [0.015 0.0537 0.0428] / pi + [0.22 0.217 0.153] * (n + 2) / (2 * pi) * b ^ n, 1e-12);
%! assert (m.e, [76 76 76]);
%! assert (m.Cxy ./ m.Cz, -0.591 / 0.548 * [1 1 1], 1e-12);

%!test
%! d = tempname (); mkdir (d);
%! unwind_protect
%!   f = fullfile (d, "n.tsv");
%!   fid = fopen (f, "w");
%!   fprintf (fid, "# comment\nmaterial\trho_d_r\trho_d_g\trho_d_b\trho_s_r\trho_s_g\trho_s_b\tCxy\tCz\tn\n");
%!   fprintf (fid, "red-plastic\t0.28\t0.0496\t0.0139\t0.25\t0.198\t0.134\t-0.63\t0.453\t23.2\n");
%!   fclose (fid);
%!   m = lafortune_ngan (f, "red-plastic");
%!   assert (m.name, "red-plastic");
%!   r = lafortune_ngan ([0.28 0.0496 0.0139], [0.25 0.198 0.134], -0.63, 0.453, 23.2);
%!   assert (m.Cxy, r.Cxy, 1e-15); assert (m.e, r.e);
%!   assert (isempty (lafortune_ngan (f, "gold")));
%!   fid = fopen (f, "w"); fprintf (fid, "name\tx\n"); fclose (fid);
%!   fail ('lafortune_ngan (f, "gold")', "must start");
%! unwind_protect_cleanup
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

%!error <Invalid call> lafortune_ngan (1, 2, 3)
%!error id=lafortune:badModel lafortune_ngan ([1 1], [1 1 1], -1, 1, 10)
%!error id=lafortune:badModel lafortune_ngan ([1 1 1], [1 1 -1], -1, 1, 10)
%!error id=lafortune:badModel lafortune_ngan ([1 1 1], [1 1 1], 0, 0, 10)
%!error id=lafortune:badModel lafortune_ngan ([1 1 1], [1 1 1], -1, 1, 0)
%!error id=lafortune:badFile lafortune_ngan ("/nonexistent/x.tsv", "a")
%!error id=lafortune:badInput lafortune_ngan (1, "a")
