## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@dots{}] =} pov_tables (@var{what}, @dots{})
## pov_write_scene's tabulation (private): everything between a material and
## the numbers of its tables, nothing of the SDL text (pov_sdl) or of the
## orchestration and options (pov_write_scene).  @var{what} is one of
## @code{"term_grid"} (a term tabulated densely on grids refined toward
## where it bends), @code{"slice_grid"} (scene_slice on (ti, inner angle)),
## @code{"gamma_levels"}, @code{"view_at_gamma"} (a perspective camera's
## levels of angle (L, V)), @code{"inner_coord"}, @code{"inner_of"},
## @code{"reach_bounds"}, @code{"reach_prep"}, @code{"reach_mask"} (the inner maps' angle and
## what normals and the view reach), @code{"masked_max"},
## @code{"masked_quantile"}, @code{"term_knots"} (a term's table cut to
## the entries pov_knots places: outer knots IO over ti, inner knots KI).  A new
## model type is tabulated here through material_eval, and can be tested
## apart from the text.
## @end deftypefn
function varargout = pov_tables (what, varargin)
  switch (what)
    case "term_knots"
      [varargout{1:max (nargout, 1)}] = term_knots (varargin{:});
    case "gamma_levels"
      [varargout{1:max (nargout, 1)}] = gamma_levels (varargin{:});
    case "view_at_gamma"
      [varargout{1:max (nargout, 1)}] = view_at_gamma (varargin{:});
    case "term_grid"
      [varargout{1:max (nargout, 1)}] = term_grid (varargin{:});
    case "reach_mask"
      [varargout{1:max (nargout, 1)}] = reach_mask (varargin{:});
    case "reach_prep"
      [varargout{1:max (nargout, 1)}] = reach_prep (varargin{:});
    case "inner_coord"
      [varargout{1:max (nargout, 1)}] = inner_coord (varargin{:});
    case "inner_of"
      [varargout{1:max (nargout, 1)}] = inner_of (varargin{:});
    case "reach_bounds"
      [varargout{1:max (nargout, 1)}] = reach_bounds (varargin{:});
    case "slice_grid"
      [varargout{1:max (nargout, 1)}] = slice_grid (varargin{:});
    case "masked_quantile"
      [varargout{1:max (nargout, 1)}] = masked_quantile (varargin{:});
    case "masked_max"
      [varargout{1:max (nargout, 1)}] = masked_max (varargin{:});
    otherwise
      error ("pov_tables: unknown part '%s'", what);
  endswitch
endfunction

## Levels of gamma = angle (L, V) for a perspective camera: the range the
## lit visible samples reach (padded), cut until linear interpolation
## between neighbouring levels of the whole material's slice, on a 65 x 65
## grid over the reached (ti, to), is within table_tol/2 of its largest
## radiance (at most 64 levels).
function gl = gamma_levels (scene, material, L, S, rng_i, rng_o, opt)
  if (isempty (S.gamma))
    gl = [0; pi/2];
    return;
  endif
  g0 = max (0, min (S.gamma) - opt.pad);
  g1 = min (pi, max (S.gamma) + opt.pad);
  t = linspace (rng_i(1), rng_i(2), 65);
  u = linspace (rng_o(1), rng_o(2), 65);
  M = reach_mask (reach_prep ([S.ti, S.to]), t', u', opt.pad);
  tab = @(g) masked (scene_slice (view_at_gamma (scene, L, g), material, t, u), M);
  gl = [g0; g1];
  R = {tab(g0), tab(g1)};
  peak = max ([R{1}(:); R{2}(:); realmin]);
  tol = opt.gamma_tol * peak;
  split = true;
  while (any (split) && numel (gl) < 64)
    split = false (numel (gl) - 1, 1);
    Rm = cell (1, numel (gl) - 1);
    for k = 1:numel (gl) - 1
      gm = (gl(k) + gl(k+1)) / 2;
      Rm{k} = tab (gm);
      err = max (abs (Rm{k}(:) - (R{k}(:) + R{k+1}(:)) / 2));
      split(k) = err > tol && gl(k+1) - gl(k) > 1e-4;
    endfor
    k = find (split);
    k = k(1:min (numel (k), 64 - numel (gl)));
    if (isempty (k))
      break;
    endif
    gn = (gl(k) + gl(k+1)) / 2;
    [gl, o] = sort ([gl; gn]);
    R = [R, Rm(k)](o);
  endwhile
endfunction

function R = masked (R, M)
  R = R .* M;
endfunction

## SCENE seen along a direction at the angle G from the light L (an
## orthographic view), for scene_slice
function sg = view_at_gamma (scene, L, g)
  p = null (L)(:,1)';
  Vg = cos (g) * L + sin (g) * p;
  sg = scene;
  sg.camera = struct ("type", "orthographic", "eye", Vg, "target", [0 0 0],
                      "up", null (Vg)(:,1)', "extent", 1, "fov", []);
endfunction

## Dense grids for one term, and its table on them.  The grids are not
## uniform: starting from a uniform one, twice, the term is tabulated and the
## points are redistributed along each axis with density proportional to the
## square root of the largest second derivative along it (the spacing that
## equalises the error of linear interpolation), plus a uniform share.  Sharp
## lobes thus get fine sampling around their peak.
function D = term_grid (scene, term, rng_i, rng_o, n, samp, opt, gam, C)
  passes = 2 * ! strcmp (opt.knots, "uniform");
  flat = false;
  n0 = n;
  if (passes)
    n0 = min (n, 129);                          # a coarse first look
  endif
  ti = linspace (rng_i(1), rng_i(2), n0)';
  to = linspace (rng_o(1), rng_o(2), n0)';
  for pass = 0:passes
    R = slice_grid (scene, term, ti, to, gam, C);
    c = cos (ti);
    [lo, hi] = reach_bounds (ti, gam, C);
    T = extend_c1 (R ./ c, ti, to, lo, hi,
                   @(t, p) slice_pairs (scene, term, t, p, gam, C) ./ cos (t));
    ## what any normal can reach (the extension beyond it only serves the
    ## interpolation next to it), and with samples what the view reaches
    M = to' >= lo - opt.pad & to' <= hi + opt.pad;
    if (! isempty (samp))
      M &= reach_mask (samp, ti, to, opt.pad);
    endif
    if (pass == passes)
      break;
    endif
    G = T .* c;
    ki = curvature (ti, G, M);
    ko = curvature (to, permute (G, [2 1 3]), M');
    if (pass == 0 && ! any (ki > 1e-9 * max (abs (G(:)))) && ! any (ko > 1e-9 * max (abs (G(:)))))
      flat = true;                              # (a diffuse term): exact with 2
      break;                                    # entries, no refining

    endif
    nn = n;
    if (pass < passes - 1)
      nn = min (n, 257);                        # an intermediate look
    endif
    ti = regrid (ti, ki, nn);
    to = regrid (to, ko, nn);
  endfor
  D.flat = flat;
  D.ti = ti;
  D.to = to;
  ## the largest radiance where a normal really reaches (no padding): past
  ## the boundary scene_slice's clamped configurations are not the scene's
  ## and a sharp lobe may be huge there
  ## and what the view reaches: M (on this grid) has it
  [lo, hi] = reach_bounds (ti, gam, C);
  M0 = to' >= lo & to' <= hi;
  D.max = masked_max (R, M0 & M);
  ## the padding and the continuation only serve the interpolation: no entry
  ## above 10 times the term's largest radiance in the view (the file then
  ## holds no 1e130 where a lobe explodes past what the view reaches)
  T = min (T, 10 * D.max ./ max (cos (ti), 1e-3));
  D.T = T;
  D.M = M;
endfunction

## largest |second derivative| along dimension 1 of G over the masked columns
function k = curvature (x, G, M)
  n = numel (x);
  d = diff (G, 1, 1) ./ diff (x);
  k2 = abs (2 * diff (d, 1, 1) ./ (x(3:end) - x(1:end-2)));
  k2(! (M(2:end-1,:) & true (size (k2)))) = 0;
  k = max (reshape (permute (k2, [1 3 2]), n - 2, []), [], 2);
  k = [k(1); k; k(end)];
endfunction

function y = regrid (x, k, n)
  r = sqrt (k);
  w = min (5, numel (r));                       # widen the peaks a little
  rr = r;
  for s = 1:w
    rr(1+s:end) = max (rr(1+s:end), r(1:end-s));
    rr(1:end-s) = max (rr(1:end-s), r(1+s:end));
  endfor
  len = x(end) - x(1);
  tot = trapz (x, rr);
  if (! (tot > 0) || ! (len > 0))
    y = linspace (x(1), x(end), n)';
    return;
  endif
  rr += 0.3 * tot / len;                        # 23 % of the points uniform
  C = cumtrapz (x, rr);
  y = interp1 (C / C(end), x, linspace (0, 1, n)');
  y([1 end]) = x([1 end]);
endfunction

## The view's samples SAMP (points x [ti, inner angle]) prepared for
## reach_mask: sorted by ti (stably), and the tables of range_minmax over
## their inner angles, made once for every grid of a view
function R = reach_prep (samp)
  [sti, o] = sort (samp(:,1));
  sto = samp(o,2);
  [Mn, Mx] = minmax_tables (sto);
  R = struct ("ti", sti, "to", sto, "Mn", Mn, "Mx", Mx);
endfunction

## reachable cells of the (ti, to) grid: for each ti row, the range of to of
## the samples within PAD of it, widened by PAD (R from reach_prep)
function Md = reach_mask (R, ti, to, pad)
  n = numel (ti);
  a = lookup (R.ti, ti - pad) + 1;              # samples a:b lie within PAD
  b = lookup (R.ti, ti + pad);
  lo = inf (n, 1);
  hi = -inf (n, 1);
  i = find (b >= a);
  if (! isempty (i))
    [lo(i), hi(i)] = range_minmax (R.Mn, R.Mx, a(i), b(i));
  endif
  Md = to' >= lo - pad & to' <= hi + pad;
endfunction

## The tables of range_minmax over X: column k of MN (MX) holds the minima
## (maxima) of the runs of 2^(k-1) values from each index, for every run
## length up to numel (X)
function [Mn, Mx] = minmax_tables (x)
  x = x(:);
  N = numel (x);
  [~, e] = log2 (max (N, 1));
  Mn = Mx = zeros (N, e);
  Mn(:,1) = Mx(:,1) = x;
  for k = 2:e
    s = 2 ^ (k - 2);
    Mn(:,k) = min (Mn(:,k-1), [Mn(s+1:end,k-1); inf(s, 1)]);
    Mx(:,k) = max (Mx(:,k-1), [Mx(s+1:end,k-1); -inf(s, 1)]);
  endfor
endfunction

## min and max of X(A(i):B(i)) for every i, all at once, from X's tables
## (minmax_tables): a run A:B is the union of two runs of 2^(k-1) values,
## from A and from B backwards
function [mn, mx] = range_minmax (Mn, Mx, a, b)
  N = rows (Mn);
  [~, k] = log2 (b - a + 1);                    # 2^(k-1) <= B - A + 1 < 2^k
  i1 = a + N * (k - 1);
  i2 = b - 2 .^ (k - 1) + 1 + N * (k - 1);
  mn = min (Mn(i1), Mn(i2));
  mx = max (Mx(i1), Mx(i2));
endfunction

## No normal reaches (ti, to) outside |ti - gamma| <= to <= ti + gamma, where
## scene_slice clamps; that leaves a crease along the boundary (the specular
## peak lies on it), which linear interpolation across it would smear over a
## whole table cell.  Continue each row linearly (in to) from the boundary
## instead: the table is then smooth to first order across it.  Extrapolated
## values are kept >= 0.
function T = extend_c1 (T, ti, to, lo, hi, evalpairs)
  n = numel (to);
  to = to(:)';
  in = to >= lo & to <= hi;                     # n x n
  ok = sum (in, 2) >= 3;
  j1 = min (n + 1 - sum (cummax (in, 2), 2), n - 1);   # first reachable column
  j2 = max (sum (cummax (fliplr (in), 2), 2), 2);      # last
  r = (1:rows (T))';
  for ch = 1:size (T, 3)
    X = T(:,:,ch);
    a1 = X(sub2ind (size (X), r, j1));
    s1 = (X(sub2ind (size (X), r, j1 + 1)) - a1) ./ (to(j1 + 1) - to(j1))';
    a2 = X(sub2ind (size (X), r, j2));
    s2 = (a2 - X(sub2ind (size (X), r, j2 - 1))) ./ (to(j2) - to(j2 - 1))';
    below = ok & (1:n) < j1;
    above = ok & (1:n) > j2;
    E1 = max (a1 + s1 .* (to - to(j1)'), 0);
    E2 = max (a2 + s2 .* (to - to(j2)'), 0);
    X(below) = E1(below);
    X(above) = E2(above);
    T(:,:,ch) = X;
  endfor
  ## rows whose reachable range holds fewer than 3 grid points (ti near 0, or
  ## light and viewer nearly aligned): 3 points across it, evaluated exactly
  bad = find (! ok);
  if (isempty (bad))
    return;
  endif
  ## their points (as linspace (lo, hi, 3) places them), evaluated in one call
  P = [lo(bad), lo(bad) + (hi(bad) - lo(bad)) / 2, hi(bad)];
  V = evalpairs (repmat (ti(bad), 3, 1), P(:));
  V = reshape (V, numel (bad), 3, []);
  for r = 1:numel (bad)
    i = bad(r);
    p = P(r,:);
    v = reshape (V(r,:,:), 3, []);              # points x channels
    if (p(3) > p(1))
      sl = (v(2,:) - v(1,:)) / (p(2) - p(1));
      sh = (v(3,:) - v(2,:)) / (p(3) - p(2));
      row = interp1 (p', v, min (max (to', p(1)), p(3)));
    else
      sl = sh = zeros (1, columns (v));
      row = repmat (v(1,:), n, 1);
    endif
    row += (to' < p(1)) .* sl .* (to' - p(1)) + (to' > p(3)) .* sh .* (to' - p(3));
    T(i,:,:) = reshape (max (row, 0), 1, n, []);
  endfor
endfunction

## The inner maps' angle (private to this file): theta_h = angle (N, H), H
## = (L + V)/|L + V|, for an orthographic camera (POV-Ray's slope toward
## H), unless L and V are nearly opposite; to = angle (N, V) otherwise
## (slope toward V; with a perspective camera the aoi pattern).
function C = inner_coord (persp, L, V)
  h = (L + V) / 2;
  C = struct ("half", ! persp && norm (h) > 0.05, "dir", V, "label", "to = angle(N,V)",
              "top", pi/2 - 1e-6, "gamma", acos (max (min (L * V', 1), -1)));
  if (C.half)
    C.dir = h / norm (h);
    C.label = "theta_h = angle(N,H), H = (L+V)/|L+V|";
    C.top = pi;
  endif
endfunction

## the inner angle of the configurations (TI, TO) (same sizes)
function u = inner_of (ti, to, C)
  u = to;
  if (C.half)
    u = __lafortune_half_angle__ (ti, to, C.gamma);
  endif
endfunction

## the range of the inner angle that some normal reaches at each TI (a
## column), at gamma = angle (L, V) = GAM: to in [|ti - gam|, ti + gam],
## theta_h in [|ti - gam/2|, ti + gam/2] (N on the cone of angle ti about
## L, which is at gam/2 from H; capped where the sums pass pi)
function [lo, hi] = reach_bounds (ti, gam, C)
  g = gam;
  if (C.half)
    g = gam / 2;
  endif
  lo = abs (ti - g);
  hi = min (ti + g, 2 * pi - ti - g);
endfunction

## scene_slice on the grid TI x U of the inner angle (numel (TI) x numel (U)
## x 3): with theta_h, to follows from cos to = 2 cos theta_h cos (gam/2) -
## cos ti (N in the frame of H: N.L + N.V = 2 cos theta_h cos (gam/2))
function R = slice_grid (scene, term, ti, u, gam, C)
  if (! C.half)
    R = scene_slice (scene, term, ti, u);
    return;
  endif
  [TI, U] = ndgrid (ti(:), u(:));
  R = reshape (slice_pairs (scene, term, TI(:), U(:), gam, C), numel (ti), numel (u), []);
endfunction

## scene_slice at the pairs (TI(i), U(i)) of the inner angle (columns):
## (slice_grid makes its grid's values here too: one definition of to)
function R = slice_pairs (scene, term, ti, u, gam, C)
  to = u;
  if (C.half)
    to = acos (min (max (2 * cos (u) * cos (gam / 2) - cos (ti), -1), 1));
    to = min (to, pi/2 - 1e-6);   # as the (ti, to) tables: continued across the
  endif                           # silhouette, where scene_slice steps to 0
  R = scene_slice (scene, term, ti, to, "pairs");
endfunction

## the Q-quantile of the largest channel of R (n x m x 3) where M
function v = masked_quantile (R, M, q)
  x = max (R, [], 3)(M & true (rows (R), columns (R)));
  v = 0;
  if (! isempty (x))
    v = quantile (x(:), q);
  endif
endfunction

function v = masked_max (R, M)
  v = 0;
  for ch = 1:size (R, 3)
    x = R(:,:,ch);
    if (any (M(:)))
      v = max (v, max (x(M)));
    endif
  endfor
endfunction

## The knots of one term's dense table DQ (term_grid): outer map over ti
## (IO), inner maps over the inner angle (KI, a column per outer knot), and
## the table T with values below 1e-12 of PEAK set to 0 (no 1e-50s in the
## file)
function [T, io, Ki] = term_knots (Dq, tol, peak, opt)
  ti = Dq.ti;
  to = Dq.to;
  T = Dq.T;
  Md = Dq.M;
  c = cos (ti);
  n = numel (ti);
  Ko = pov_knots (ti, reshape (T, n, 3 * n), c, repmat (Md, 1, 3), tol, opt.entries,
                  opt.knots);
  io = find (Ko);
  ## each inner table serves the ti between its neighbours
  lo = io([1 1:end-1]);
  hi = io([2:end end]);
  cs = [zeros(1, n); cumsum(Md, 1)];
  Mi = (cs(hi+1,:) - cs(lo,:))' > 0;                     # n x numel(io)
  G = permute (T(io,:,:), [2 3 1]);                      # n x 3 x numel(io)
  Ki = pov_knots (to, G, reshape (c(io), 1, 1, []), reshape (Mi, n, 1, []), tol,
                  opt.entries, opt.knots);
  T(abs (T) < 1e-12 * peak) = 0;
endfunction
