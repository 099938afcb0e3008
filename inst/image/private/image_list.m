## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {[@var{tests}, @var{several}] =} image_list (@var{ref}, @var{test}, @var{check}, @var{fname})
## The test images of a comparison (private, img_flip and img_deltae): @var{test}
## is one image or a non-empty cell array of them; each is checked by
## @var{check} (a handle that validates and converts one image) and must
## have the size of @var{ref}.  @var{tests} is a cell array, @var{several}
## true when @var{test} was one.
## @end deftypefn
function [tests, several] = image_list (ref, test, check, fname)
  several = iscell (test);
  tests = test;
  if (! several)
    tests = {test};
  elseif (isempty (test))
    error ("lafortune:badImage", "%s: TEST must be an image or a non-empty cell array of images",
           fname);
  endif
  for i = 1:numel (tests)
    tests{i} = check (tests{i});
    if (! isequal (size (ref), size (tests{i})))
      error ("lafortune:badImage", "%s: REF and TEST must have the same size, got %s and %s",
             fname, mat2str (size (ref)), mat2str (size (tests{i})));
    endif
  endfor
endfunction
