## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{db} =} img_psnr (@var{ref}, @var{img})
## @deftypefnx {lafortune} {[@var{db}, @var{mse}, @var{peak}] =} img_psnr (@var{ref}, @var{img})
## Peak signal-to-noise ratio of @var{img} against the reference @var{ref}, in dB.
##
## Convention, used everywhere in this toolbox: the peak is the reference's
## maximum, @code{peak = max (ref(:))}, and the mean squared error is taken
## over all pixels and channels:
## @code{db = 10 log10 (peak^2 / mean ((ref(:) - img(:)).^2))}.
## Linear HDR images are compared as they are (no tone mapping).  Identical
## images give Inf.
##
## @example
## @group
## ref = rand (64, 64, 3);
## db = img_psnr (ref, ref + 0.01 * randn (64, 64, 3))   # near 10 log10 (1 / 0.01^2)
## @end group
## @end example
## @seealso{img_diff}
## @end deftypefn
function [db, mse, peak] = img_psnr (ref, img)
  if (nargin != 2)
    print_usage ();
  endif
  if (! isnumeric (ref) || ! isnumeric (img) || ! isreal (ref) || ! isreal (img))
    error ("lafortune:badImage", "img_psnr: REF and IMG must be real numeric arrays");
  endif
  if (! isequal (size (ref), size (img)))
    error ("lafortune:badImage", "img_psnr: REF and IMG must have the same size, got %s and %s",
           mat2str (size (ref)), mat2str (size (img)));
  endif
  if (isempty (ref) || ! all (isfinite (ref(:))) || ! all (isfinite (img(:))))
    error ("lafortune:badImage", "img_psnr: REF and IMG must be non-empty and finite");
  endif
  peak = max (double (ref(:)));
  if (! (peak > 0))
    error ("lafortune:badImage", "img_psnr: the reference's maximum must be > 0 (it is the peak)");
  endif
  mse = mean ((double (ref(:)) - double (img(:))) .^ 2);
  db = 10 * log10 (peak ^ 2 / mse);
endfunction

%!test
%! ref = [0 0.5; 1 0.25];
%! assert (img_psnr (ref, ref), Inf);
%! img = ref + [0.1 -0.1; 0.1 -0.1];
%! assert (img_psnr (ref, img), 20, 1e-12);
%! [db, mse, peak] = img_psnr (2 * ref, 2 * img);
%! assert ([db mse peak], [20 0.04 2], 1e-12);

%!error <Invalid call> img_psnr (1)
%!error <same size> img_psnr (ones (2), ones (3))
%!error <must be > 0> img_psnr (zeros (2), ones (2))
%!error id=lafortune:badImage img_psnr ([1 NaN], [1 1])
%!error id=lafortune:badImage img_psnr ("ab", "ab")
