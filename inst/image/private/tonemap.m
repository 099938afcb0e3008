## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{rgb}, @var{exposure}] =} tonemap (@var{img}, @var{exposure}, @var{fname})
## Linear HDR image to 8-bit sRGB (private): exposure in stops or "auto",
## clamp, sRGB curve, uint8.  See img_tonemap and img_write_png.
## @end deftypefn
function [rgb, exposure] = tonemap (img, exposure, fname)
  if (! (isa (img, "double") || isa (img, "single")) || ! isreal (img)
      || ndims (img) != 3 || size (img, 3) != 3 || isempty (img))
    desc = describe (img);
    error ("lafortune:badImage",
           "%s: IMG must be a real double or single H x W x 3 array, got %s",
           fname, desc);
  endif
  img = double (img);

  if (ischar (exposure))
    if (! strcmpi (exposure, "auto"))
      error ("lafortune:badExposure",
             "%s: EXPOSURE must be a finite real scalar (stops) or \"auto\", got \"%s\"",
             fname, exposure);
    endif
    Y = __lafortune_luminance__ (img);
    Y = sort (Y(isfinite (Y)));
    if (isempty (Y))
      exposure = 0;
    else
      p99 = Y(ceil (0.99 * numel (Y)));
      if (p99 > 0)
        exposure = -log2 (p99);
      else
        exposure = 0;
      endif
    endif
  elseif (! (isnumeric (exposure) && isreal (exposure) && isscalar (exposure)
             && isfinite (exposure)))
    error ("lafortune:badExposure",
           "%s: EXPOSURE must be a finite real scalar (stops) or \"auto\"", fname);
  endif
  exposure = double (exposure);

  c = img * 2^exposure;
  c(isnan (c)) = 0;
  c = min (max (c, 0), 1);
  lo = c <= 0.0031308;
  c(lo) = 12.92 * c(lo);
  c(! lo) = 1.055 * c(! lo) .^ (1 / 2.4) - 0.055;
  rgb = uint8 (round (255 * c));

endfunction
