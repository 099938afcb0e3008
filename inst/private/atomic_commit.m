## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} atomic_commit (@var{tmp}, @var{file}, @var{fname})
## Rename the finished temporary @var{tmp} onto @var{file} (private).  On
## failure the temporary is removed and @code{lafortune:unwritable} raised;
## @var{file} is left as it was.
## @end deftypefn
function atomic_commit (tmp, file, fname)
  [err, msg] = rename (tmp, file);
  if (err)
    unlink (tmp);
    error ("lafortune:unwritable", "%s: cannot replace '%s': %s", fname, file, msg);
  endif
endfunction
