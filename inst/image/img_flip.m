## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{err} =} img_flip (@var{ref}, @var{test})
## @deftypefnx {lafortune} {[@var{err}, @var{map}, @var{info}] =} img_flip (@var{ref}, @var{test}, @var{name}, @var{value}, @dots{})
## FLIP difference of @var{test} against the reference @var{ref}: the
## perceived difference when flipping between the two images, per pixel in
## [0, 1] (0: no visible difference).
##
## @var{ref} and @var{test} are @var{H} x @var{W} x 3 real images of the
## same size.  By default they are linear HDR renders (double or single) and
## are compared with HDR-FLIP (Andersson et al. 2021): each is exposed by
## 2^@var{e} for a series of exposures @var{e} (stops), tone mapped with
## the ACES fit of Narkowicz (with FLIP's pre-exposure cancellation of 0.6)
## and clamped to [0, 1], LDR-FLIP compares each tone-mapped pair, and the
## error of a pixel is its largest over the exposures.  With
## @code{"ldr", true} the images are display images with sRGB-encoded values
## in [0, 1] (uint8 images are divided by 255; values outside [0, 1] are
## clamped) and are compared with LDR-FLIP (Andersson et al. 2020).
##
## LDR-FLIP filters both images, in the opponent space YCxCz, with the
## contrast sensitivity functions of the achromatic, red-green and
## blue-yellow channels at @qcode{"ppd"} pixels per degree, takes the HyAB
## distance of the Hunt-adjusted CIELAB colours raised to 0.7 and maps it to
## [0, 1] (the first 40 % of the largest distance, green against blue, to
## [0, 0.95]).  The difference of edges and points (first and second
## derivatives of a Gaussian of standard deviation 0.082 / 2 degrees, on
## the luminance) raises this colour error to the power 1 minus the feature
## error.  The map is computed in single precision, as in the FLIP tool.
##
## Options (names are case-insensitive):
## @table @asis
## @item @qcode{"ppd"} (67.02)
## Pixels per degree of visual angle (0.7 m from a 0.7 m wide 4K screen).
## @item @qcode{"start"}, @qcode{"stop"}, @qcode{"exposures"}
## The first and last exposure in stops and their count, evenly spaced
## (HDR only; a count of 1 is the start alone).  What is not given follows
## HDR-FLIP's rule, computed over the reference's object pixels (luminance
## > 0) rather than the whole image: @code{start = log2 (x85 / Ymax)},
## @code{stop = log2 (x85 / Ymedian)} (the upper median),
## @code{exposures = max (2, ceil (stop - start))}, where
## @var{x85} is the value the tone mapper maps to 0.85.  A render on a black
## background has median 0 over the whole image, which would give an
## infinite stop.  A reference without a positive pixel is an error unless
## both @qcode{"start"} and @qcode{"stop"} are given.
## @item @qcode{"mask"} (the pixels where either image is non-zero)
## @var{H} x @var{W} logical: the pixels @var{err} and the statistics of
## @var{info} are pooled over.
## @item @qcode{"ldr"} (false)
## Compare sRGB display images with LDR-FLIP.
## @end table
##
## @var{err} is the mean of @var{map} over the mask (0 when the default mask
## is empty: both images are black), @var{map} the @var{H} x @var{W} error
## map and @var{info} a struct with fields @code{start}, @code{stop},
## @code{exposures} (empty for LDR), @code{ppd}, @code{mean_all} (the mean
## over all pixels, as the FLIP tool pools), @code{median} and @code{max}
## (over the mask).  The error is not symmetric in @var{ref} and @var{test}.
##
## @var{test} may be a cell array of images: then @var{err} is a row of
## their errors, @var{map} a cell array of their maps and @var{info} a
## struct array, each the same as comparing that image alone; the
## reference's part (its exposures, tone-mapped, filtered and converted
## images, edges and points) is made once for all of them.
##
## @example
## @group
## ref = exrread ("measured.exr");
## [err, map, info] = img_flip (ref, exrread ("fit.exr"));
## printf ("FLIP %.4f (exposures %.2f to %.2f, %d)\n", err,
##         info.start, info.stop, info.exposures);
## imshow (map, [0 1]); colormap (hot ());
## @end group
## @end example
## @seealso{img_psnr, img_deltae}
## @end deftypefn
function [err, map, info] = img_flip (ref, test, varargin)
  if (nargin < 2)
    print_usage ();
  endif
  fname = "img_flip";
  opt = __lafortune_parse_opts__ (varargin, fname, struct ("ppd", 67.02, "start", [], "stop", [],
                                             "exposures", [], "mask", [], "ldr", false));
  ldr = opt.ldr;
  if (! isscalar (ldr) || ! (islogical (ldr) || (isnumeric (ldr) && isreal (ldr)
                                                 && any (ldr == [0 1]))))
    error ("lafortune:badOption", "%s: \"ldr\" must be a logical scalar", fname);
  endif
  ldr = logical (ldr);
  ref = check_image (ref, "REF", ldr, fname);
  [test, several] = image_list (ref, test, @(x) check_image (x, "TEST", ldr, fname), fname);
  [H, W, ~] = size (ref);

  ppd = opt.ppd;
  if (! (isnumeric (ppd) && isreal (ppd) && isscalar (ppd) && isfinite (ppd) && ppd > 0))
    error ("lafortune:badOption",
           "%s: \"ppd\" must be a positive finite scalar (pixels per degree)", fname);
  endif
  ppd = double (ppd);
  for nm = {"start", "stop"}
    v = opt.(nm{1});
    if (! isempty (v) && ! (isnumeric (v) && isreal (v) && isscalar (v) && isfinite (v)))
      error ("lafortune:badOption", "%s: \"%s\" must be a finite real scalar (stops)",
             fname, nm{1});
    endif
  endfor
  n = opt.exposures;
  if (! isempty (n) && ! (isnumeric (n) && isreal (n) && isscalar (n) && isfinite (n)
                          && n == round (n) && n >= 1))
    error ("lafortune:badOption",
           "%s: \"exposures\" must be an integer count of at least 1", fname);
  endif
  mask = opt.mask;
  if (! isempty (mask))
    if (! (islogical (mask) || (isnumeric (mask) && isreal (mask)
                                && all (mask(:) == 0 | mask(:) == 1)))
        || ! isequal (size (mask), [H W]))
      error ("lafortune:badOption",
             "%s: \"mask\" must be a %d x %d logical array (the image's size), got %s %s",
             fname, H, W, mat2str (size (mask)), class (mask));
    endif
    mask = logical (mask);
    if (! any (mask(:)))
      error ("lafortune:badOption", "%s: \"mask\" selects no pixel", fname);
    endif
  endif

  F = flip_filters (ppd);
  info = struct ("start", [], "stop", [], "exposures", [], "ppd", ppd,
                 "mean_all", 0, "median", 0, "max", 0);
  if (! ldr)
    [e0, e1, n] = exposures (ref, opt.start, opt.stop, n, fname);
    info.start = e0;
    info.stop = e1;
    info.exposures = n;
    step = 0;
    if (n > 1)
      step = (e1 - e0) / (n - 1);
    endif
    expo = e0 + step * (0:n-1);
  else
    expo = [];
  endif

  ## A pixel farther than the filters reach from every non-zero pixel has
  ## error 0 (both images are 0 there in every exposure, and so are their
  ## filtered colours and features): compute only the box around the
  ## non-zero pixels, with a margin of zeros (so edges extended at the box
  ## are the zeros beyond it).  This is exact, and fast on renders on a
  ## black background.  The reference's part is made once, on the box its
  ## own object pixels give; a test whose object reaches beyond it gets its
  ## own box (the box decides the filters' border, so it is the pair's)
  nzref = any (ref != 0, 3);
  P = [];
  nt = numel (test);
  err = zeros (1, nt);
  maps = cell (1, nt);
  infos = repmat (info, 1, nt);
  for i = 1:nt
    nz = nzref | any (test{i} != 0, 3);
    [ri, ci] = crop (nz, F.reach);
    m = zeros (H, W);
    if (! isempty (ri))
      if (isempty (P) || ! isequal (P.ri, ri) || ! isequal (P.ci, ci))
        P = prepare (ref, ri, ci, expo, ldr, F);
      endif
      m(ri, ci) = double (compare (P, test{i}(ri, ci, :), expo, ldr, F));
    endif
    pool = mask;
    if (isempty (pool))
      pool = nz;
    endif
    infos(i).mean_all = mean (m(:));
    if (any (pool(:)))
      v = m(pool);
      err(i) = mean (v);
      infos(i).median = median (v);
      infos(i).max = max (v);
    endif
    maps{i} = m;
  endfor
  if (several)
    map = maps;
    info = infos;
  else
    map = maps{1};
    info = infos(1);
  endif
endfunction

## the rows and columns of the pixels within REACH of the non-zero ones
function [ri, ci] = crop (nz, reach)
  [H, W] = size (nz);
  ri = find (any (nz, 2));
  ci = find (any (nz, 1));
  if (! isempty (ri))
    ri = max (ri(1) - reach, 1):min (ri(end) + reach, H);
    ci = max (ci(1) - reach, 1):min (ci(end) + reach, W);
  endif
endfunction

## the reference's part on a crop: per exposure, its opponent colours, their
## filtered values and colours, and its edges and points
function P = prepare (ref, ri, ci, expo, ldr, F)
  P = struct ("ri", ri, "ci", ci);
  R = single (ref(ri, ci, :));    # single precision, as the FLIP tool
  if (ldr)
    P.side = {side(srgb_linear (R), F)};
  else
    P.side = cell (1, numel (expo));
    for j = 1:numel (expo)
      P.side{j} = side (aces (R, 2 ^ expo(j)), F);
    endfor
  endif
endfunction

## the test's part on the same crop, and the per-pixel error: the largest
## over the exposures
function sub = compare (P, T, expo, ldr, F)
  T = single (T);                 # computes: faster, and ample here
  if (ldr)
    sub = ldr_flip (P.side{1}, side (srgb_linear (T), F), F);
  else
    sub = zeros (numel (P.ri), numel (P.ci), "single");
    for j = 1:numel (expo)
      sub = max (sub, ldr_flip (P.side{j}, side (aces (T, 2 ^ expo(j)), F), F));
    endfor
  endif
endfunction

function img = check_image (img, name, ldr, fname)
  if (ldr)
    want = "real double, single or uint8 H x W x 3 array";
    ok = isa (img, "double") || isa (img, "single") || isa (img, "uint8");
  else
    want = "real double or single H x W x 3 array (linear HDR; uint8 needs \"ldr\", true)";
    ok = isa (img, "double") || isa (img, "single");
  endif
  if (! ok || ! isreal (img) || ndims (img) != 3 || size (img, 3) != 3 || isempty (img))
    cplx = "";
    if (isnumeric (img) && ! isreal (img))
      cplx = "complex ";
    endif
    error ("lafortune:badImage", "%s: %s must be a %s, got %s %s%s", fname, name, want,
           mat2str (size (img)), cplx, class (img));
  endif
  if (isa (img, "uint8"))
    img = double (img) / 255;
  else
    img = double (img);
  endif
  if (! all (isfinite (img(:))))
    error ("lafortune:badImage", "%s: %s must be finite (no NaN or Inf)", fname, name);
  endif
endfunction

## The exposures: given values, the rest from HDR-FLIP's rule on the
## reference's object pixels.
function [e0, e1, n] = exposures (ref, e0, e1, n, fname)
  if (isempty (e0) || isempty (e1))
    Y = __lafortune_luminance__ (ref);
    Y = sort (Y(Y > 0));
    if (isempty (Y))
      error ("lafortune:badImage",
             ["%s: REF has no pixel of positive luminance to choose exposures ", ...
              "from; give \"start\" and \"stop\""], fname);
    endif
    x85 = aces_inverse (0.85);
    if (isempty (e0))
      e0 = log2 (x85 / Y(end));
    endif
    if (isempty (e1))
      e1 = log2 (x85 / Y(floor (numel (Y) / 2) + 1));   # upper median
    endif
  endif
  e0 = double (e0);
  e1 = double (e1);
  if (e0 > e1)
    error ("lafortune:badOption", "%s: \"start\" (%g) must not exceed \"stop\" (%g)",
           fname, e0, e1);
  endif
  if (isempty (n))
    n = max (2, ceil (e1 - e0));
  endif
  n = double (n);
endfunction

## Narkowicz's fit of the ACES filmic curve, applied to 0.6 s x (FLIP
## cancels the fit's built-in pre-exposure of 0.6), clamped to [0, 1].
function y = aces (x, s)
  x = (0.6 * s) * x;
  y = (x .* (2.51 * x + 0.03)) ./ (x .* (2.43 * x + 0.59) + 0.14);
  y = min (max (y, 0), 1);
endfunction

## The linear value that aces maps to t (the larger root of the quadratic).
function x = aces_inverse (t)
  a = 2.51 - t * 2.43;
  b = 0.03 - t * 0.59;
  c = -t * 0.14;
  x = (-b + sqrt (b ^ 2 - 4 * a * c)) / (2 * a) / 0.6;
endfunction

## sRGB-encoded [0, 1] values to linear ones.
function c = srgb_linear (c)
  c = min (max (c, 0), 1);
  lo = c <= 0.04045;
  c(lo) = c(lo) / 12.92;
  c(! lo) = ((c(! lo) + 0.055) / 1.055) .^ 2.4;
endfunction

## Everything that depends on ppd only: the CSF filters, the feature
## filters and the colour constants.
function F = flip_filters (ppd)
  ## linear RGB -> XYZ from the sRGB primaries and the D65 white, divided by
  ## the white (T); the opponent space YCxCz is linear in it (O): rows
  ## 116 Y (Y* + 16), 500 (X - Y) (Cx) and 200 (Y - Z) (Cz)
  F.T = srgb_xyz ();
  O = [0 116 0; 500 -500 0; 0 200 -200];
  F.A = O * F.T;
  F.Ainv = inv (F.A);

  ## CSFs as sums of Gaussians a sqrt(pi/b) exp(-pi^2 x^2 / b), x in degrees
  a1 = [1 1 34.1];  b1 = [0.0047 0.0053 0.04];
  a2 = [0 0 13.5];  b2 = [1e-5 1e-5 0.025];
  r = ceil (3 * sqrt (max ([b1 b2]) / (2 * pi ^ 2)) * ppd);
  x2 = ((-r:r)' / ppd) .^ 2;
  F.gY = gauss_unit (exp (-pi ^ 2 * x2 / b1(1)));
  F.gCx = gauss_unit (exp (-pi ^ 2 * x2 / b1(2)));
  ## blue-yellow: the 2-D sum k1 k1' + k2 k2' of two separable terms
  k1 = sqrt (a1(3) * sqrt (pi / b1(3))) * exp (-pi ^ 2 * x2 / b1(3));
  k2 = sqrt (a2(3) * sqrt (pi / b2(3))) * exp (-pi ^ 2 * x2 / b2(3));
  s = sqrt (sum (k1) ^ 2 + sum (k2) ^ 2);
  F.gCz1 = k1 / s;
  F.gCz2 = k2 / s;

  ## feature detectors: Gaussian of standard deviation 0.082 / 2 degrees
  ## and its first and second derivatives (each sign part normalised to 1)
  sd = 0.5 * 0.082 * ppd;
  rf = ceil (3 * sd);
  k = (-rf:rf)';
  g = exp (-k .^ 2 / (2 * sd ^ 2));
  F.g = g / sum (g);
  F.d1 = signed_unit (-k .* g);
  F.d2 = signed_unit ((k .^ 2 / sd ^ 2 - 1) .* g);
  F.reach = max (r, rf) + 1;

  ## colour error: HyAB ^ 0.7 (see hyab), the largest (green against blue)
  ## cmax, mapped linearly to [0, pt] up to pc cmax and to [pt, 1] above: a
  ## concave broken line, the smaller of its two lines
  pt = 0.95;
  pc = 0.4;
  lab = hunt_lab ([0 1 0; 0 0 1] * F.T');
  cmax = hyab (lab(1,:), lab(2,:));
  F.lo = [pt / (pc * cmax), 0];
  F.hi = [(1 - pt) / ((1 - pc) * cmax), pt - pc * (1 - pt) / (1 - pc)];

  ## the images are filtered in single precision
  for f = {"T", "A", "Ainv", "gY", "gCx", "gCz1", "gCz2", "g", "d1", "d2", "lo", "hi"}
    F.(f{1}) = single (F.(f{1}));
  endfor
endfunction

function g = gauss_unit (g)
  g = g / sum (g);
endfunction

function d = signed_unit (d)
  p = sum (d(d > 0));
  m = -sum (d(d < 0));
  if (p > 0)
    d(d > 0) /= p;
  endif
  if (m > 0)
    d(d < 0) /= m;
  endif
endfunction

## White-relative XYZ rows (N x 3) -> CIELAB with the Hunt adjustment (a*
## and b* times L*/100).
function lab = hunt_lab (t)
  d3 = (6 / 29) ^ 3;
  lo = t <= d3;
  f = t .^ (1 / 3);                   # t >= 0
  if (any (lo(:)))
    f(lo) = t(lo) / (3 * (6 / 29) ^ 2) + 4 / 29;
  endif
  L = 116 * f(:,2) - 16;
  lab = [L, (5 * L) .* (f(:,1) - f(:,2)), (2 * L) .* (f(:,2) - f(:,3))];
endfunction

## HyAB distance raised to qc = 0.7.
function d = hyab (p, q)
  d = (abs (p(:,1) - q(:,1)) + hypot (p(:,2) - q(:,2), p(:,3) - q(:,3))) .^ 0.7;
endfunction

## Edges extended by r pixels on each side.
function A = extend (A, r)
  [h, w] = size (A);
  A = A(min (max ((1 - r):(h + r), 1), h), min (max ((1 - r):(w + r), 1), w));
endfunction

## Separable filtering with the column kernel u along both axes, edges
## extended (two 1-D passes: faster than conv2's separable form).
function B = filt (A, u)
  r = (numel (u) - 1) / 2;
  B = conv2 (conv2 (extend (A, r), u, "valid"), u', "valid");
endfunction

## The CSF-filtered opponent channels (N x 3) of the H x W image Z (N x 3).
function Z = csf (Z, H, W, F)
  Y = filt (reshape (Z(:,1), H, W), F.gY);
  Cx = filt (reshape (Z(:,2), H, W), F.gCx);
  Cz = reshape (Z(:,3), H, W);
  Cz = filt (Cz, F.gCz1) + filt (Cz, F.gCz2);
  Z = [Y(:), Cx(:), Cz(:)];
endfunction

## Edge and point responses of the luminance Y (H x W, white-relative):
## magnitudes of the first and second derivatives over x and y.
function [e, p] = features (Y, F)
  r = (numel (F.g) - 1) / 2;
  Y = extend (Y, r);
  Gx = conv2 (Y, F.g', "valid");      # smoothed along x: (H + 2r) x W
  dx = conv2 (conv2 (Y, F.d1', "valid"), F.g, "valid");
  ddx = conv2 (conv2 (Y, F.d2', "valid"), F.g, "valid");
  dy = conv2 (Gx, F.d1, "valid");
  ddy = conv2 (Gx, F.d2, "valid");
  e = hypot (dx, dy);
  p = hypot (ddx, ddy);
endfunction

## LDR-FLIP error map of two linear RGB images in [0, 1].
## one image's part of LDR-FLIP: its filtered colours (and their Hunt-adjusted
## CIELAB values) and its edges and points
function S = side (X, F)
  [H, W, ~] = size (X);
  N = H * W;
  z = reshape (X, N, 3) * F.A';
  ## colour: filtered opponent colours back to linear RGB, clamped to the
  ## gamut, Hunt-adjusted CIELAB
  S.f = csf (z, H, W, F);
  S.lab = lab_of (S.f, F);
  ## features of the luminance (white-relative Y, in [0, 1])
  [S.e, S.p] = features (reshape (z(:,1), H, W) / 116, F);
endfunction

function map = ldr_flip (r, t, F)
  [H, W] = size (r.e);
  ## HyAB of the colours; 0 where the filtered colours are the same
  d = hyab (r.lab, t.lab);
  dc = min (d * F.lo(1) + F.lo(2), d * F.hi(1) + F.hi(2));
  dc(! any (r.f != t.f, 2)) = 0;
  df = sqrt (max (abs (r.e - t.e), abs (r.p - t.p)) / sqrt (2));   # exponent qf = 0.5
  map = min (max (reshape (dc, H, W) .^ (1 - df), 0), 1);
endfunction

function lab = lab_of (Z, F)
  lab = hunt_lab (min (max (Z * F.Ainv', 0), 1) * F.T');
endfunction

%!demo
%! ## a highlight rendered slightly too broad and too dim on a grey sphere
%! [x, y] = meshgrid (linspace (-1, 1, 160), linspace (-1, 1, 120));
%! inside = x .^ 2 + y .^ 2 < 0.8;
%! spot = @(w, h) h * exp (-((x - 0.3) .^ 2 + (y + 0.3) .^ 2) / w);
%! ref = inside .* (0.2 + spot (0.01, 20)) .* reshape ([1 0.9 0.8], 1, 1, 3);
%! test = inside .* (0.2 + spot (0.015, 12)) .* reshape ([1 0.9 0.8], 1, 1, 3);
%! [err, map, info] = img_flip (ref, test);
%! printf ("FLIP %.4f over the sphere, exposures %.2f to %.2f (%d)\n",
%!         err, info.start, info.stop, info.exposures);
%! imshow (map, [0 1]); colormap (hot ()); colorbar ();

%!shared ref, test
%! [x, y] = meshgrid (linspace (-1, 1, 48), linspace (-1, 1, 40));
%! inside = x .^ 2 + y .^ 2 < 0.7;
%! ref = inside .* (0.3 + 4 * exp (-((x - 0.2) .^ 2 + y .^ 2) / 0.02));
%! ref = ref .* reshape ([1 0.8 0.6], 1, 1, 3);
%! test = ref .* reshape ([1.1 0.9 1], 1, 1, 3);
%! test(10:14,20:24,:) += 0.5;

%!test
%! [err, map, info] = img_flip (ref, ref);
%! assert (err, 0);
%! assert (map, zeros (40, 48));
%! assert (info.mean_all, 0);
%! [err, map] = img_flip (ref, ref, "ldr", true, "mask", true (40, 48));
%! assert (err, 0);
%! assert (map, zeros (40, 48));

%!test
%! [err, map, info] = img_flip (ref, test);
%! assert (size (map), [40 48]);
%! assert (all (map(:) >= 0 & map(:) <= 1));
%! inside = any (ref != 0, 3) | any (test != 0, 3);
%! assert (err, mean (map(inside)), 1e-12);
%! assert (info.mean_all, mean (map(:)), 1e-12);
%! assert (info.median, median (map(inside)), 1e-12);
%! assert (info.max, max (map(inside)), 1e-12);
%! assert (info.ppd, 67.02);
%! assert (err > info.mean_all && err > 0);
%! ## the mask changes what is pooled, not the map
%! m = false (40, 48);
%! m(10:14,20:24) = true;
%! [err2, map2] = img_flip (ref, test, "mask", m);
%! assert (map2, map);
%! assert (err2, mean (map(m)), 1e-12);
%! assert (err2 != err);
%! ## options are case-insensitive; single images give the same map
%! [~, map3] = img_flip (single (ref), single (test), "PPD", 67.02);
%! assert (map3, map, 1e-5);

%!test
%! ## several test images: each as compared alone, bit for bit, also one
%! ## whose object reaches beyond the reference's (a crop of its own)
%! far = ref;
%! far(1:3,1:3,:) = 0.7;
%! T = {test, 0.9 * ref, far, single(ref)};
%! [err, map, info] = img_flip (ref, T);
%! assert (size (err), [1 4]);
%! for i = 1:4
%!   [e1, m1, i1] = img_flip (ref, T{i});
%!   assert (err(i), e1);
%!   assert (map{i}, m1);
%!   assert (info(i), i1);
%! endfor
%! assert (err(4), 0);
%! [e2, m2] = img_flip (ref, {test, far}, "ldr", true, "mask", true (40, 48));
%! assert (e2, [img_flip(ref, test, "ldr", true, "mask", true (40, 48)), ...
%!              img_flip(ref, far, "ldr", true, "mask", true (40, 48))]);

%!test
%! ## the default exposures follow the rule on the object pixels
%! [~, map, info] = img_flip (ref, test);
%! Y = 0.2126 * ref(:,:,1) + 0.7152 * ref(:,:,2) + 0.0722 * ref(:,:,3);
%! Y = sort (Y(Y > 0));
%! t = 0.85;                          # ACES(0.6 x) = t: quadratic in 0.6 x
%! q = roots ([2.51 - 2.43 * t, 0.03 - 0.59 * t, -0.14 * t]);
%! x85 = max (q) / 0.6;
%! assert (info.start, log2 (x85 / Y(end)), 1e-12);
%! assert (info.stop, log2 (x85 / Y(floor (numel (Y) / 2) + 1)), 1e-12);
%! assert (info.exposures, max (2, ceil (info.stop - info.start)));
%! [~, map2] = img_flip (ref, test, "start", info.start, "stop", info.stop,
%!                       "exposures", info.exposures);
%! assert (map2, map);
%! ## what is not given follows the rule
%! [~, ~, i3] = img_flip (ref, test, "exposures", 5);
%! assert ([i3.start i3.stop i3.exposures], [info.start info.stop 5], 1e-12);
%! [~, ~, i4] = img_flip (ref, test, "start", -1, "stop", 2.5);
%! assert ([i4.start i4.stop i4.exposures], [-1 2.5 4]);
%! [~, ~, i5] = img_flip (ref, test, "start", info.start - 1);
%! assert ([i5.start i5.stop], [info.start - 1, info.stop], 1e-12);
%! ## more exposures can only raise the per-pixel maximum (same end points)
%! [~, m2] = img_flip (ref, test, "start", -2, "stop", 2, "exposures", 2);
%! [~, m5] = img_flip (ref, test, "start", -2, "stop", 2, "exposures", 5);
%! assert (all (m5(:) >= m2(:)));

%!test
%! ## uniform images: no edges or points, the colour pipeline alone decides.
%! ## Pure green against pure blue is the largest colour distance: 1.
%! g = zeros (8, 9, 3); g(:,:,2) = 1;
%! b = zeros (8, 9, 3); b(:,:,3) = 1;
%! [err, map] = img_flip (g, b, "ldr", true);
%! assert (map, ones (8, 9), 1e-12);
%! assert (err, 1, 1e-12);
%! ## greys g1, g2 (linear): L* = 116 g^(1/3) - 16, a* = b* = 0, so the
%! ## error is (116 |g1^(1/3) - g2^(1/3)|)^0.7 scaled by 0.95 / (0.4 cmax)
%! ## with cmax the Hunt-adjusted HyAB distance of green and blue, ^0.7
%! lab = @(L, a, b) [L, L / 100 * a, L / 100 * b];
%! xyz = [0.4124 0.3576 0.1805; 0.2126 0.7152 0.0722; 0.0193 0.1192 0.9505];
%! w = [0.95047 1 1.08883];
%! f = @(t) cbrt (t);
%! tg = xyz(:,2)' ./ w;  tb = xyz(:,3)' ./ w;
%! Lab = @(t) lab (116 * f (t(2)) - 16, 500 * (f (t(1)) - f (t(2))), 200 * (f (t(2)) - f (t(3))));
%! G = Lab (tg);
%! B = Lab (tb);
%! cmax = (abs (G(1) - B(1)) + norm (G(2:3) - B(2:3))) ^ 0.7;
%! g1 = 0.2; g2 = 0.25;
%! want = (116 * abs (g1 ^ (1/3) - g2 ^ (1/3))) ^ 0.7 * 0.95 / (0.4 * cmax);
%! s = @(c) 1.055 * c ^ (1 / 2.4) - 0.055;     # display encoding
%! [err, map] = img_flip (s (g1) * ones (6, 7, 3), s (g2) * ones (6, 7, 3), "ldr", true);
%! assert (map, want * ones (6, 7), 1e-4);
%! ## the same greys in HDR: one exposure of 0 stops tone maps them first
%! aces = @(x) (0.36 * 2.51 * x ^ 2 + 0.018 * x) / (0.36 * 2.43 * x ^ 2 + 0.354 * x + 0.14);
%! h1 = 0.3; h2 = 0.5;
%! want = (116 * abs (aces (h1) ^ (1/3) - aces (h2) ^ (1/3))) ^ 0.7 * 0.95 / (0.4 * cmax);
%! [err, map, info] = img_flip (h1 * ones (5, 5, 3), h2 * ones (5, 5, 3),
%!                              "start", 0, "stop", 0, "exposures", 1);
%! assert (map, want * ones (5, 5), 1e-4);
%! assert (info.exposures, 1);

%!test
%! ## LDR on uint8 is LDR on the values / 255
%! u = uint8 (round (255 * min (ref, 1)));
%! v = uint8 (round (255 * min (test, 1)));
%! [e1, m1] = img_flip (u, v, "ldr", true);
%! [e2, m2] = img_flip (double (u) / 255, double (v) / 255, "ldr", true);
%! assert (m1, m2, 1e-12);
%! assert (e1, e2, 1e-12);
%! assert (e1 > 0);
%! ## a lower ppd (a closer viewer) changes the map
%! [~, m3] = img_flip (u, v, "ldr", true, "ppd", 20);
%! assert (any (abs (m3(:) - m1(:)) > 1e-3));

%!error id=lafortune:badImage img_flip (ones (2, 2, 3), {})
%!error id=lafortune:badImage img_flip (ones (2, 2, 3), {ones(2, 2, 3), ones(2, 3, 3)})
%!error <Invalid call> img_flip (ones (4, 4, 3))
%!error id=lafortune:badImage img_flip (ones (4, 4), ones (4, 4))
%!error <H x W x 3> img_flip (ones (4, 4, 4), ones (4, 4, 4))
%!error <same size> img_flip (ones (4, 4, 3), ones (4, 5, 3))
%!error <finite> img_flip (NaN (4, 4, 3), ones (4, 4, 3))
%!error <finite> img_flip (ones (4, 4, 3), Inf (4, 4, 3))
%!error <complex> img_flip (complex (ones (4, 4, 3)), ones (4, 4, 3))
%!error <needs "ldr"> img_flip (uint8 (ones (4, 4, 3)), uint8 (ones (4, 4, 3)))
%!error id=lafortune:badImage img_flip ("abc", "abc")
%!error <no pixel of positive luminance> img_flip (zeros (4, 4, 3), ones (4, 4, 3))
%!error <"ppd" must be a positive> img_flip (ones (4, 4, 3), ones (4, 4, 3), "ppd", -1)
%!error id=lafortune:badOption img_flip (ones (4, 4, 3), ones (4, 4, 3), "ppd", [1 2])
%!error <must not exceed> img_flip (ones (4, 4, 3), ones (4, 4, 3), "start", 2, "stop", 1)
%!error <must not exceed> img_flip (ones (4, 4, 3), ones (4, 4, 3), "start", 5)
%!error <"start" must be a finite> img_flip (ones (4, 4, 3), ones (4, 4, 3), "start", Inf)
%!error <integer count of at least 1> img_flip (ones (4, 4, 3), ones (4, 4, 3), "exposures", 0)
%!error <integer count of at least 1> img_flip (ones (4, 4, 3), ones (4, 4, 3), "exposures", 2.5)
%!error <must be a 4 x 4 logical> img_flip (ones (4, 4, 3), ones (4, 4, 3), "mask", true (4, 5))
%!error <selects no pixel> img_flip (ones (4, 4, 3), ones (4, 4, 3), "mask", false (4, 4))
%!error <"ldr" must be a logical> img_flip (ones (4, 4, 3), ones (4, 4, 3), "ldr", "yes")
%!error <unknown option 'gamma'> img_flip (ones (4, 4, 3), ones (4, 4, 3), "gamma", 2)
%!error <NAME, VALUE pairs> img_flip (ones (4, 4, 3), ones (4, 4, 3), "ppd")
