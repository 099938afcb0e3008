## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{done}, @dots{}] =} __lafortune_oct_call__ (@var{name}, @var{who}, @dots{})
## Call the compiled inner loop @var{name} (an oct-file of @file{src/}) with
## the remaining arguments, when it is built (internal, for every area that
## has a compiled inner loop): @var{done} is true
## and its outputs follow.  Otherwise @var{done} is false, and the caller
## does the same arithmetic in Octave, which is the definition.  An oct-file
## that does not load (built for another Octave) raises the warning
## @code{lafortune:noOctFile} once, naming @var{who}, and is not tried
## again; the oct-file's own errors (@code{lafortune:@dots{}}) are the
## caller's.
## @end deftypefn
function [done, varargout] = __lafortune_oct_call__ (name, who, varargin)
  persistent broken = {};
  done = false;
  varargout = cell (1, max (nargout - 1, 0));
  if (exist (name, "file") != 3 || any (strcmp (broken, name)))
    return;
  endif
  try
    [varargout{1:nargout-1}] = feval (name, varargin{:});
    done = true;
  catch err
    if (strncmp (err.identifier, "lafortune:", 10))
      rethrow (err);
    endif
    broken{end+1} = name;
    warning ("lafortune:noOctFile",
             "%s: the oct-file %s does not work (%s); using the Octave arithmetic (rebuild it: make -C src)",
             who, name, err.message);
  end_try_catch
endfunction

%!test
%! ## an oct-file that is not there: not done, no outputs made
%! [done, a] = __lafortune_oct_call__ ("__lafortune_no_such_oct__", "test", 1);
%! assert (done, false);
%! assert (isempty (a));

%!test
%! ## a built oct-file: done, with its outputs
%! x = (0:10)';
%! [done, k] = __lafortune_oct_call__ ("__pov_knots__", "test", x, abs (x - 4), ones (11, 1),
%!                                     true (11, 1), 1e-9, 8, [1 11]);
%! assert (done, true);
%! assert (k, [1; 5; 11]);

%!error id=lafortune:badInput __lafortune_oct_call__ ("__pov_knots__", "test", (1:4)', ones (4, 2), ones (4, 2), true (4, 2), 0, -1, [1 4])
