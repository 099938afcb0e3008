## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{de} =} img_deltae (@var{ref}, @var{test})
## @deftypefnx {lafortune} {[@var{de}, @var{s}] =} img_deltae (@var{ref}, @var{test}, @var{name}, @var{value}, @dots{})
## Per-pixel colour difference of the image @var{test} against the
## reference @var{ref}, and its statistics over the object's pixels.
##
## @var{ref} and @var{test} are @var{H} x @var{W} x 3 real, finite, double
## or single linear HDR images (Rec.@: 709 / sRGB primaries, white D65) of the
## same size.  @var{de} is the @var{H} x @var{W} (double) colour difference
## of each pixel.  The exposure, in stops, is decided on the reference and
## applied to both images, as @code{img_tonemap} does: a number, or
## @qcode{"auto"} (the default), which maps the reference's 99th percentile
## of the luminance to 1.
##
## Options:
## @table @asis
## @item @qcode{"metric"} (@qcode{"ciede2000"})
## @qcode{"ciede2000"}: the CIEDE2000 difference (kL = kC = kH = 1; Sharma,
## Wu and Dalal 2005) of the images as the display shows them: each linear
## value times 2^exposure, clamped to [0, 1] (sRGB-encoding and decoding
## that back changes nothing, as no 8-bit rounding is done), converted to
## CIELAB (white: the display's white, rgb = [1 1 1]).
## @qcode{"itp"}: Delta E ITP of ITU-R BT.2124 on the linear images, not
## clamped: a linear value v is shown at v * 2^exposure * @var{nits}
## cd/m^2, converted to ICtCp (BT.2100, PQ of SMPTE ST 2084; negative light
## counts as 0), and
## @code{de = 720 sqrt (dI^2 + dT^2 + dP^2)} with T = Ct / 2, P = Cp.
## With the default exposure the reference's 99th percentile of the
## luminance is shown at @var{nits}, and brighter pixels above it.
## @item @qcode{"exposure"} (@qcode{"auto"})
## stops, or @qcode{"auto"} (from @var{ref}), for both metrics.
## @item @qcode{"nits"} (100)
## the luminance in cd/m^2 at which a linear value 1 (after the exposure)
## is shown, for @qcode{"itp"} only.
## @item @qcode{"mask"} ([]: the object)
## @var{H} x @var{W} logical: the pixels pooled in @var{s}.  The default is
## every pixel where either image is non-zero in some channel (renders of an
## object on a black background).
## @item @qcode{"input"} (@qcode{"rgb"})
## @qcode{"lab"}: @var{ref} and @var{test} are CIELAB values already
## (@var{H} x @var{W} x 3, or N x 3, taken as N x 1 x 3) and only the
## CIEDE2000 formula is applied (metric @qcode{"ciede2000"} only; the
## exposure is not used).
## @end table
##
## @var{s} is a struct: @code{mean}, @code{median}, @code{p95} (the
## 95th percentile: the sorted values' element ceil (0.95 n)) of @var{de}
## over the mask; @code{hue}, the chroma-weighted mean hue difference in
## degrees (below); @code{npix}, the number of pixels pooled; and
## @code{metric}, @code{exposure} (the stops applied, NaN for
## @qcode{"input"} @qcode{"lab"}) and @code{nits} (NaN for
## @qcode{"ciede2000"}).  With no pixel in the mask the statistics are NaN
## and @code{npix} is 0.
##
## @var{test} may be a cell array of images: then @var{de} is a cell array
## and @var{s} a struct array, each the same as comparing that image alone;
## the reference's exposure and colours are computed once for all of them.
##
## The hue statistic tells a fit whose colour has drifted from one that is
## only brighter or darker.  It is computed in CIELAB of the displayed images
## (as for @qcode{"ciede2000"}, with either metric): per pixel, the weight is
## the reference's chroma C*ab (0 where that is below 1: its hue is
## undefined) and dh the absolute difference of the hue angles, in
## [0, 180] degrees, taken as 90 (the mean of a random hue difference) where
## the test's chroma is below 1;
## @code{hue = sum (w .* dh) / sum (w)}, NaN when sum (w) = 0.
##
## @example
## @group
## b = merl_standin ("red-plastic");
## scene = scene_make ("sphere", "size", 96);
## ref = rt_render (scene, b);
## img = rt_render (scene, lafortune_fit (merl_plane (b), 1));
## [de, s] = img_deltae (ref, img);
## printf ("mean %.2f, 95%% %.2f, hue %.1f deg\n", s.mean, s.p95, s.hue);
## imagesc (de); axis image; colorbar;
## @end group
## @end example
## @seealso{img_psnr, img_flip}
## @end deftypefn
function [de, s] = img_deltae (ref, test, varargin)
  if (nargin < 2)
    print_usage ();
  endif
  fname = "img_deltae";
  opt = __lafortune_parse_opts__ (varargin, fname, struct ("metric", "ciede2000", "exposure", "auto",
                                             "nits", 100, "mask", [], "input", "rgb"));
  metrics = {"ciede2000", "itp"};
  if (! ischar (opt.metric) || ! any (strcmpi (opt.metric, metrics)))
    error ("lafortune:badOption",
           "%s: \"metric\" must be \"ciede2000\" or \"itp\", got '%s'",
           fname, __lafortune_arg_str__ (opt.metric));
  endif
  metric = lower (opt.metric);
  if (! ischar (opt.input) || ! any (strcmpi (opt.input, {"rgb", "lab"})))
    error ("lafortune:badOption", "%s: \"input\" must be \"rgb\" or \"lab\", got '%s'",
           fname, __lafortune_arg_str__ (opt.input));
  endif
  lab = strcmpi (opt.input, "lab");
  if (lab && strcmp (metric, "itp"))
    error ("lafortune:badOption",
           "%s: \"input\" \"lab\" works with metric \"ciede2000\" only (\"itp\" needs linear RGB)",
           fname);
  endif
  if (! (isnumeric (opt.nits) && isreal (opt.nits) && isscalar (opt.nits)
         && isfinite (opt.nits) && opt.nits > 0))
    error ("lafortune:badOption", "%s: \"nits\" must be a positive finite scalar (cd/m^2)",
           fname);
  endif
  ref = check_image (ref, "REF", lab, fname);
  [test, several] = image_list (ref, test, @(x) check_image (x, "TEST", lab, fname), fname);
  [h, w, ~] = size (ref);
  n = h * w;
  mask = opt.mask;
  if (! isempty (mask) && (! (islogical (mask) || (isnumeric (mask) && isreal (mask)
                                                   && all (mask(:) == 0 | mask(:) == 1)))
                           || ! isequal (size (mask), [h w])))
    got = describe (mask);
    error ("lafortune:badOption",
           "%s: \"mask\" must be a %dx%d logical array (the images' H x W), got %s",
           fname, h, w, got);
  endif
  ## the reference's part, once for every test image
  A = reshape (ref, n, 3);
  nzA = any (A != 0, 2);
  if (lab)
    exposure = NaN;
    labA = A;
  else
    [~, exposure] = tonemap (ref, opt.exposure, fname);
    k = 2 ^ exposure;
    if (strcmp (metric, "ciede2000") || nargout > 1)
      labA = srgb_to_lab (min (max (A * k, 0), 1));
    endif
    if (strcmp (metric, "itp"))
      nits = double (opt.nits);
      iA = ictcp (A * (k * nits));
    endif
  endif
  nt = numel (test);
  des = cell (1, nt);
  for i = 1:nt
    B = reshape (test{i}, n, 3);
    nz = nzA | any (B != 0, 2);          # the object: either pixel non-zero
    if (lab)
      labB = B;
    elseif (strcmp (metric, "ciede2000") || nargout > 1)
      labB = srgb_to_lab (min (max (B * k, 0), 1));
    endif
    if (strcmp (metric, "ciede2000"))
      ## where both pixels are black (rgb input) both colours are 0 and so is
      ## the difference: the formula is applied to the others alone
      de = zeros (n, 1);
      on = nz | lab;
      de(on) = ciede2000 (labA(on,:), labB(on,:));
      nits = NaN;
    else
      d = iA - ictcp (B * (k * nits));
      de = 720 * sqrt (d(:,1).^2 + (d(:,2) / 2).^2 + d(:,3).^2);
    endif
    des{i} = reshape (de, h, w);
    if (nargout > 1)
      if (isempty (mask))
        m = nz;
      else
        m = logical (mask(:));
      endif
      si = struct ("mean", NaN, "median", NaN, "p95", NaN, "hue", NaN, "npix", nnz (m),
                   "metric", metric, "exposure", exposure, "nits", nits);
      if (si.npix > 0)
        v = de(m);
        si.mean = mean (v);
        si.median = median (v);
        si.p95 = nth_element (v, ceil (0.95 * numel (v)));
        a = labA(m,:);
        b = labB(m,:);
        Ca = sqrt (a(:,2).^2 + a(:,3).^2);
        Cb = sqrt (b(:,2).^2 + b(:,3).^2);
        dh = abs (atan2d (a(:,3), a(:,2)) - atan2d (b(:,3), b(:,2)));
        dh = min (dh, 360 - dh);
        dh(Cb < 1) = 90;
        wt = Ca .* (Ca >= 1);
        if (sum (wt) > 0)
          si.hue = sum (wt .* dh) / sum (wt);
        endif
      endif
      s(i) = si;
    endif
  endfor
  if (several)
    de = des;
  else
    de = des{1};
  endif
endfunction

function x = check_image (x, name, lab, fname)
  ok = (isa (x, "double") || isa (x, "single")) && isreal (x) && ! isempty (x);
  if (lab)
    shape = "H x W x 3 or N x 3 array of CIELAB values";
    ok = ok && ((ndims (x) == 3 && size (x, 3) == 3) || (ismatrix (x) && columns (x) == 3));
  else
    shape = "H x W x 3 image";
    ok = ok && ndims (x) == 3 && size (x, 3) == 3;
  endif
  if (! ok)
    got = describe (x);
    error ("lafortune:badImage", "%s: %s must be a real double or single %s, got %s",
           fname, name, shape, got);
  endif
  if (! all (isfinite (x(:))))
    error ("lafortune:badImage", "%s: %s must be finite (it has NaN or Inf values)",
           fname, name);
  endif
  x = double (x);
  if (ismatrix (x))
    x = reshape (x, rows (x), 1, 3);
  endif
endfunction

%!test
%! ## several test images: each as compared alone, bit for bit
%! [y, x] = ndgrid (linspace (-1, 1, 30), linspace (-1, 1, 36));
%! disc = x .^ 2 + y .^ 2 < 0.5;
%! ref = disc .* cat (3, 0.4, 0.2, 0.1) .* (1 + 3 * exp (-((x - 0.2) .^ 2 + y .^ 2) / 0.03));
%! T = {1.2 * ref, ref(:,:,[2 1 3]), circshift(ref, [2 2]), zeros(30, 36, 3)};
%! for metric = {"ciede2000", "itp"}
%!   [de, s] = img_deltae (ref, T, "metric", metric{1});
%!   assert (size (de), [1 4]);
%!   for i = 1:4
%!     [d1, s1] = img_deltae (ref, T{i}, "metric", metric{1});
%!     assert (de{i}, d1);
%!     assert (isequaln (s(i), s1));
%!   endfor
%! endfor
%!error id=lafortune:badImage img_deltae (ones (2, 2, 3), {})
%!error id=lafortune:badImage img_deltae (ones (2, 2, 3), {ones(2, 2, 3), ones(2, 3, 3)})

%!test
%! ## the 34 pairs of Sharma, Wu and Dalal (2005), Table 1: L1 a1 b1 L2 a2 b2 dE00
%! t = [
%!       50.0000   2.6772 -79.7751  50.0000   0.0000 -82.7485   2.0425
%!       50.0000   3.1571 -77.2803  50.0000   0.0000 -82.7485   2.8615
%!       50.0000   2.8361 -74.0200  50.0000   0.0000 -82.7485   3.4412
%!       50.0000  -1.3802 -84.2814  50.0000   0.0000 -82.7485   1.0000
%!       50.0000  -1.1848 -84.8006  50.0000   0.0000 -82.7485   1.0000
%!       50.0000  -0.9009 -85.5211  50.0000   0.0000 -82.7485   1.0000
%!       50.0000   0.0000   0.0000  50.0000  -1.0000   2.0000   2.3669
%!       50.0000  -1.0000   2.0000  50.0000   0.0000   0.0000   2.3669
%!       50.0000   2.4900  -0.0010  50.0000  -2.4900   0.0009   7.1792
%!       50.0000   2.4900  -0.0010  50.0000  -2.4900   0.0010   7.1792
%!       50.0000   2.4900  -0.0010  50.0000  -2.4900   0.0011   7.2195
%!       50.0000   2.4900  -0.0010  50.0000  -2.4900   0.0012   7.2195
%!       50.0000  -0.0010   2.4900  50.0000   0.0009  -2.4900   4.8045
%!       50.0000  -0.0010   2.4900  50.0000   0.0010  -2.4900   4.8045
%!       50.0000  -0.0010   2.4900  50.0000   0.0011  -2.4900   4.7461
%!       50.0000   2.5000   0.0000  50.0000   0.0000  -2.5000   4.3065
%!       50.0000   2.5000   0.0000  73.0000  25.0000 -18.0000  27.1492
%!       50.0000   2.5000   0.0000  61.0000  -5.0000  29.0000  22.8977
%!       50.0000   2.5000   0.0000  56.0000 -27.0000  -3.0000  31.9030
%!       50.0000   2.5000   0.0000  58.0000  24.0000  15.0000  19.4535
%!       50.0000   2.5000   0.0000  50.0000   3.1736   0.5854   1.0000
%!       50.0000   2.5000   0.0000  50.0000   3.2972   0.0000   1.0000
%!       50.0000   2.5000   0.0000  50.0000   1.8634   0.5757   1.0000
%!       50.0000   2.5000   0.0000  50.0000   3.2592   0.3350   1.0000
%!       60.2574 -34.0099  36.2677  60.4626 -34.1751  39.4387   1.2644
%!       63.0109 -31.0961  -5.8663  62.8187 -29.7946  -4.0864   1.2630
%!       61.2901   3.7196  -5.3901  61.4292   2.2480  -4.9620   1.8731
%!       35.0831 -44.1164   3.7933  35.0232 -40.0716   1.5901   1.8645
%!       22.7233  20.0904 -46.6940  23.0331  14.9730 -42.5619   2.0373
%!       36.4612  47.8580  18.3852  36.2715  50.5065  21.2231   1.4146
%!       90.8027  -2.0831   1.4410  91.1528  -1.6435   0.0447   1.4441
%!       90.9257  -0.5406  -0.9208  88.6381  -0.8985  -0.7239   1.5381
%!        6.7747  -0.2908  -2.4247   5.8714  -0.0985  -2.2286   0.6377
%!        2.0776   0.0795  -1.1350   0.9033  -0.0636  -0.5514   0.9082 ];
%! de = img_deltae (t(:,1:3), t(:,4:6), "input", "lab");
%! assert (size (de), [34 1]);
%! assert (de, t(:,7), 1e-4);
%! assert (img_deltae (t(:,4:6), t(:,1:3), "input", "lab"), t(:,7), 1e-4);
%! ## H x W x 3 Lab arrays, and the statistics
%! [de, s] = img_deltae (reshape (t(:,1:3), 17, 2, 3), reshape (t(:,4:6), 17, 2, 3),
%!                       "input", "lab");
%! assert (de, reshape (t(:,7), 17, 2), 1e-4);
%! assert ([s.npix s.mean s.median], [34 mean(de(:)) median(de(:))], 1e-12);
%! v = sort (de(:));
%! assert (s.p95, v(33));
%! assert (isnan (s.exposure) && isnan (s.nits));
%! assert (s.metric, "ciede2000");

%!test
%! ## identical images: 0 with both metrics
%! r = rand (8, 9, 3) .^ 2;
%! for m = {"ciede2000", "itp"}
%!   [de, s] = img_deltae (r, r, "metric", m{1});
%!   assert (de, zeros (8, 9));
%!   assert ([s.mean s.median s.p95 s.hue s.npix], [0 0 0 0 72]);
%!   assert (s.metric, m{1});
%! endfor

%!test
%! ## Delta E ITP by hand from the published constants (BT.2100, ST 2084, BT.2087)
%! pq = @(y) ((3424/4096 + 2413/128 * y.^(2610/16384)) ./ (1 + 2392/128 * y.^(2610/16384))).^(2523/32);
%! M = [1688 2146 262; 683 2951 462; 99 309 3688] / 4096 ...
%!     * [0.6274 0.3293 0.0433; 0.0691 0.9195 0.0114; 0.0164 0.0880 0.8956];
%! itp = @(rgb) pq (rgb * M' / 1e4) * ([2048 2048 0; 6610 -13613 7003; 17933 -17390 -543] / 4096)';
%! dei = @(p, q) 720 * norm ((itp (p) - itp (q)) .* [1 0.5 1]);
%! ## a grey and the same grey 1% brighter: I only, at 50 cd/m^2 (exposure 0)
%! g = 0.5 * ones (3, 4, 3);
%! [de, s] = img_deltae (g, 1.01 * g, "metric", "itp", "exposure", 0);
%! assert (de, repmat (720 * (pq (50.5e-4) - pq (50e-4)), 3, 4), 1e-10);
%! assert (dei ([50 50 50], [50.5 50.5 50.5]), de(1), 1e-10);
%! assert ([s.exposure s.nits], [0 100]);
%! ## "auto" puts the reference's grey at "nits"
%! [de, s] = img_deltae (g, 1.01 * g, "metric", "itp", "nits", 200);
%! assert (s.exposure, 1);
%! assert (de, repmat (720 * (pq (202e-4) - pq (200e-4)), 3, 4), 1e-10);
%! ## colours: the matrices through XYZ agree with BT.2087's rounded one
%! p = [0.2 0.5 0.1];  q = [0.22 0.47 0.13];
%! de = img_deltae (reshape (p, 1, 1, 3), reshape (q, 1, 1, 3), "metric", "itp",
%!                  "exposure", 0, "nits", 300);
%! assert (de, dei (300 * p, 300 * q), 1e-3 * de);
%! ## black against black: 0, and nothing pooled by default
%! [de, s] = img_deltae (zeros (4, 5, 3), zeros (4, 5, 3), "metric", "itp");
%! assert (de, zeros (4, 5));
%! assert (s.npix, 0);
%! assert (isnan ([s.mean s.median s.p95 s.hue]));
%! [de, s] = img_deltae (zeros (4, 5, 3), zeros (4, 5, 3), "metric", "itp", "mask", true (4, 5));
%! assert ([s.npix s.mean s.hue], [20 0 NaN]);

%!test
%! ## mask pooling: the default pools the pixels non-zero in either image
%! r = zeros (4, 4, 3);
%! r(2:3,2:3,:) = 0.5;
%! t = r;
%! t(2,2,:) = 0.6;
%! t(4,4,:) = 0.1;
%! [de, s] = img_deltae (r, t, "exposure", 0);
%! k = false (4); k(2:3,2:3) = true; k(4,4) = true;
%! assert (s.npix, 5);
%! assert (s.mean, mean (de(k)), 1e-12);
%! assert (s.median, median (de(k)), 1e-12);
%! assert (s.p95, max (de(k)));
%! assert (de(! k), zeros (11, 1));
%! assert (de(2,2) > 0 && de(4,4) > de(2,2));
%! [de2, s] = img_deltae (r, t, "exposure", 0, "mask", true (4));
%! assert (de2, de);
%! assert ([s.npix s.mean], [16 sum(de(:)) / 16], 1e-12);
%! [~, s] = img_deltae (r, t, "exposure", 0, "mask", double (k));
%! assert (s.npix, 5);
%! [~, s] = img_deltae (r, t, "mask", false (4));
%! assert (s.npix, 0);
%! assert (isnan ([s.mean s.median s.p95 s.hue]));

%!test
%! ## exposure "auto" is decided on the reference and applied to both
%! r = 0.25 * ones (5, 6, 3);
%! r(:,:,1) = 0.2;
%! t = 4 * r;
%! [de, s] = img_deltae (r, t);
%! e = -log2 (0.2126 * 0.2 + 0.7874 * 0.25);
%! assert (s.exposure, e, 1e-12);
%! assert (de, img_deltae (r, t, "exposure", e), 1e-12);
%! assert (all (de(:) > 5));              # the test is clipped to white
%! [~, s2] = img_deltae (t, r);
%! assert (s2.exposure, e - 2, 1e-12);
%! ## scaling both images changes nothing with "auto"
%! assert (img_deltae (8 * r, 8 * t), de, 1e-12);
%! [de, s] = img_deltae (r, t, "metric", "itp");
%! assert (s.exposure, e, 1e-12);
%! assert (img_deltae (8 * r, 8 * t, "metric", "itp"), de, 1e-9);

%!test
%! ## the hue statistic tells a grey sphere from a teal one
%! [x, y] = meshgrid (linspace (-1, 1, 64));
%! z = sqrt (max (1 - x.^2 - y.^2, 0));
%! teal = z .* reshape ([0.05 0.4 0.4], 1, 1, 3);
%! grey = repmat (z * ([0.2126 0.7152 0.0722] * [0.05; 0.4; 0.4]), [1 1 3]);
%! near = 1.04 * teal .* (1 + 0.03 * sin (7 * x + 11 * y + reshape ([0 2 4], 1, 1, 3)));
%! for m = {"ciede2000", "itp"}
%!   [~, sg] = img_deltae (teal, grey, "metric", m{1});
%!   [~, sn] = img_deltae (teal, near, "metric", m{1});
%!   assert (sg.npix, nnz (z > 0));
%!   assert (sg.hue > 45);
%!   assert (sn.hue < 5);
%! endfor
%! ## achromatic reference pixels weigh nothing
%! [~, s] = img_deltae (grey, teal);
%! assert (isnan (s.hue));

%!test
%! ## single images give the double result
%! r = rand (6, 7, 3);
%! t = r .* reshape ([1.1 1 0.9], 1, 1, 3);
%! for m = {"ciede2000", "itp"}
%!   de = img_deltae (r, t, "metric", m{1});
%!   ds = img_deltae (single (r), single (t), "metric", m{1});
%!   assert (class (ds), "double");
%!   assert (ds, de, 1e-3);
%! endfor

%!error <Invalid call> img_deltae ()
%!error <Invalid call> img_deltae (ones (2, 2, 3))
%!error <REF must be finite> img_deltae (NaN (2, 2, 3), ones (2, 2, 3))
%!error <TEST must be finite> img_deltae (ones (2, 2, 3), Inf (2, 2, 3))
%!error <got 2x2x3 complex double> img_deltae (complex (ones (2, 2, 3), 1), ones (2, 2, 3))
%!error <same size, got \[2 2 3\] and \[2 3 3\]> img_deltae (ones (2, 2, 3), ones (2, 3, 3))
%!error <H x W x 3 image, got 2x2x2 double> img_deltae (ones (2, 2, 2), ones (2, 2, 2))
%!error <TEST must be .* got 4x3 double> img_deltae (ones (2, 2, 3), ones (4, 3))
%!error <got 2x2x3 uint8> img_deltae (uint8 (ones (2, 2, 3)), ones (2, 2, 3))
%!error <got cell> img_deltae ({1}, ones (2, 2, 3))
%!error <got 0x0x3 double> img_deltae (zeros (0, 0, 3), zeros (0, 0, 3))
%!error id=lafortune:badImage img_deltae (ones (2, 2, 3), ones (2, 2, 4))
%!error <"metric" must be "ciede2000" or "itp", got 'cie76'> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "metric", "cie76")
%!error <"metric" .* got 'double'> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "metric", 1)
%!error <"input" must be "rgb" or "lab", got 'xyz'> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "input", "xyz")
%!error <"lab" works with metric "ciede2000" only> img_deltae (ones (2, 3), ones (2, 3), "input", "lab", "metric", "itp")
%!error <"nits" must be a positive> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "metric", "itp", "nits", 0)
%!error <"nits"> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "nits", [1 2])
%!error <"nits"> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "nits", NaN)
%!error <"mask" must be a 2x2 logical array .*got 3x3 logical> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "mask", true (3))
%!error <"mask" .*got 2x2 double> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "mask", 2 * ones (2))
%!error <"mask" .*got 1x2 char> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "mask", "ab")
%!error <"mask" must be a 3x1 .*got 1x3 logical> img_deltae (ones (3, 3), ones (3, 3), "input", "lab", "mask", true (1, 3))
%!error <unknown option 'colour'> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "colour", 1)
%!error <NAME, VALUE pairs> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "metric")
%!error id=lafortune:badExposure img_deltae (ones (2, 2, 3), ones (2, 2, 3), "exposure", "bright")
%!error <img_deltae: EXPOSURE> img_deltae (ones (2, 2, 3), ones (2, 2, 3), "exposure", NaN)
%!error <N x 3 array of CIELAB values, got 4x2 double> img_deltae (ones (4, 2), ones (4, 2), "input", "lab")
%!error <REF must be finite> img_deltae ([NaN 0 0], [1 0 0], "input", "lab")

%!demo
%! ## a measured material's render against its 1-lobe fit's
%! b = merl_standin ("red-plastic");
%! scene = scene_make ("sphere", "size", 96);
%! ref = rt_render (scene, b);
%! img = rt_render (scene, lafortune_fit (merl_plane (b), 1));
%! [de, s] = img_deltae (ref, img);
%! [~, si] = img_deltae (ref, img, "metric", "itp");
%! printf ("CIEDE2000: mean %.2f, median %.2f, 95%% %.2f; hue %.1f deg\n",
%!         s.mean, s.median, s.p95, s.hue);
%! printf ("ITP: mean %.2f, 95%% %.2f (%d pixels)\n", si.mean, si.p95, si.npix);
%! imagesc (de); axis image; colorbar; title ("CIEDE2000, fit against reference");
