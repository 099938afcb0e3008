## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{nbytes} =} write_text (@var{fid}, @var{parts})
## Write a string or a cell of strings to @var{fid} (private, a writer for
## atomic_write): the number of bytes written, or -1 when fputs failed.
## @end deftypefn
function nbytes = write_text (fid, parts)
  if (ischar (parts))
    parts = {parts};
  endif
  nbytes = 0;
  for k = 1:numel (parts)
    if (fputs (fid, parts{k}) != 0)
      nbytes = -1;
      return;
    endif
    nbytes += numel (parts{k});
  endfor
endfunction
