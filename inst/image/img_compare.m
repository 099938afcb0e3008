## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{q} =} img_compare (@var{ref}, @var{img})
## @deftypefnx {lafortune} {@var{q} =} img_compare (@var{ref}, @{@var{img1}, @var{img2}, @dots{}@})
## @deftypefnx {lafortune} {@var{q} =} img_compare (@dots{}, @var{name}, @var{value}, @dots{})
## How far a render @var{img} is from the reference render @var{ref}, by
## every measure the toolbox reports: the one place where a comparison's
## numbers are made, for the pipelines, the tour and a user's own renders.
##
## @var{ref} and @var{img} are linear HDR images (@var{H} x @var{W} x 3) of
## the same scene, typically the measured material's render and a fit's.
## @var{q} is a struct:
## @table @code
## @item psnr
## @code{img_psnr (ref, img)}, dB (peak: the reference's maximum).
## @item flip
## HDR-FLIP (@code{img_flip}, its default exposures, from the reference's
## object pixels): the mean per-pixel error over the pixels where either
## image is non-zero, 0 (same) to 1.
## @item deltae
## the mean CIEDE2000 difference of the displayed images
## (@code{img_deltae}, exposure "auto" from the reference) over the same
## pixels.
## @item hue
## @code{img_deltae}'s hue statistic: the chroma-weighted mean hue-angle
## difference in degrees (a highlight or body of the wrong colour).
## @end table
## With a cell array of renders, @var{q} is a struct array, one element per
## render, each the same as @code{img_compare (ref, img@var{i})}: what
## depends on the reference alone (its exposures, its filtered images and
## colours) is computed once for all of them, so comparing several fits with
## one reference costs less than comparing them one at a time.
## Options: @qcode{"maps"}, true: also @code{q.flip_map} and
## @code{q.deltae_map} (@var{H} x @var{W}).  Lower FLIP, ΔE and hue and
## higher PSNR are better.  PSNR is dominated by the highlight's peak;
## FLIP and ΔE see the body colour and the highlight's shape as a viewer
## does.
##
## @example
## @group
## b = merl_standin ("red-plastic");
## scene = scene_make ("sphere", "size", 64);
## ref = rt_render (scene, b);
## q = img_compare (ref, rt_render (scene, lafortune_fit (merl_plane (b), 2)))
## @end group
## @end example
## @seealso{img_psnr, img_flip, img_deltae}
## @end deftypefn
function q = img_compare (ref, img, varargin)
  if (nargin < 2)
    print_usage ();
  endif
  opt = __lafortune_parse_opts__ (varargin, "img_compare", struct ("maps", false));
  if (! (isscalar (opt.maps) && (islogical (opt.maps) || isnumeric (opt.maps))))
    error ("lafortune:badOption", "img_compare: MAPS must be true or false");
  endif
  several = iscell (img);
  if (several && isempty (img))
    error ("lafortune:badImage", "img_compare: IMG must be an image or a non-empty cell array of images");
  endif
  imgs = img;
  if (! several)
    imgs = {img};
  endif
  [flip, fmap] = img_flip (ref, imgs);
  [dmap, s] = img_deltae (ref, imgs);
  for i = numel (imgs):-1:1
    q(i).psnr = img_psnr (ref, imgs{i});
    q(i).flip = flip(i);
    q(i).deltae = s(i).mean;
    q(i).hue = s(i).hue;
    if (opt.maps)
      q(i).flip_map = fmap{i};
      q(i).deltae_map = dmap{i};
    endif
  endfor
endfunction

%!test
%! ref = zeros (32, 48, 3);
%! [y, x] = ndgrid (linspace (-1, 1, 32), linspace (-1, 1, 48));
%! disc = x .^ 2 + y .^ 2 < 0.6;
%! ref = disc .* cat (3, 0.05, 0.3, 0.28) .* (1 + 0.5 * x);
%! q = img_compare (ref, ref);
%! assert ([q.psnr q.flip q.deltae q.hue], [Inf 0 0 0]);
%! ## a grey disc of the same luminance: the colour is wrong
%! Y = 0.2126 * ref(:,:,1) + 0.7152 * ref(:,:,2) + 0.0722 * ref(:,:,3);
%! grey = repmat (Y, 1, 1, 3);
%! g = img_compare (ref, grey, "maps", true);
%! assert (g.hue > 45);
%! assert (g.deltae > 10);
%! assert (g.flip > 0.1);
%! assert (size (g.flip_map), [32 48]);
%! assert (size (g.deltae_map), [32 48]);
%! ## a slightly brighter teal disc: the colour is right
%! b = img_compare (ref, 1.05 * ref);
%! assert (b.hue < 1);
%! assert (b.flip < g.flip / 3);
%! assert (b.deltae < g.deltae / 3);

%!test
%! ## several renders against one reference: each as compared alone
%! [y, x] = ndgrid (linspace (-1, 1, 40), linspace (-1, 1, 30));
%! disc = x .^ 2 + y .^ 2 < 0.6;
%! ref = disc .* cat (3, 0.3, 0.2, 0.1) .* (1 + 4 * exp (-((x - 0.2) .^ 2 + y .^ 2) / 0.02));
%! imgs = {1.1 * ref, ref .* cat(3, 1, 1.2, 0.8), disc .* cat(3, 0.2, 0.2, 0.2), circshift(ref, [0 3])};
%! q = img_compare (ref, imgs, "maps", true);
%! assert (size (q), [1 4]);
%! for i = 1:4
%!   assert (q(i), img_compare (ref, imgs{i}, "maps", true));
%! endfor
%! assert (q(4).flip > q(1).flip);

%!error <Invalid call> img_compare (ones (2, 2, 3))
%!error id=lafortune:badImage img_compare (ones (2, 2, 3), {})
%!error id=lafortune:badImage img_compare (ones (2, 2, 3), {ones(2, 2, 3), ones(3, 2, 3)})
%!error id=lafortune:badImage img_compare (ones (2, 2, 3), ones (3, 2, 3))
%!error id=lafortune:badOption img_compare (ones (2, 2, 3), ones (2, 2, 3), "maps", "yes")
%!error id=lafortune:badOption img_compare (ones (2, 2, 3), ones (2, 2, 3), "colour", 1)
