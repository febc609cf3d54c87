"""The `tmm` command line: parse, call the core, hand the result to the renderers.

Heavy modules (numpy, scipy, matplotlib, the core) are imported inside the commands, so
``tmm --help`` stays instant. Every bad input becomes one line on stderr and exit status 2.
"""

from __future__ import annotations

import os
import sys

import click

from .commands.assign import assign_cmd
from .commands.batch import batch_cmd
from .commands.cam import cam_cmd
from .commands.carrier import carrier_cmd
from .commands.chain import chain_cmd
from .commands.check import check_cmd
from .commands.gears import gears_cmd
from .commands.linkage import linkage_cmd
from .commands.note import note_cmd
from .commands.options import CONTEXT, apply_option_limits, lang_option
from .commands.planetary import planetary_cmd
from .commands.project import project_cmd
from .commands.synth import synth_cmd
from .commands.variants import variants_cmd
from .errors import TmmError
from .i18n import N_


class TmmGroup(click.Group):
    """A click group whose errors are one line on stderr with exit status 2, never a traceback."""

    def main(self, args=None, prog_name=None, complete_var=None, standalone_mode=True, **extra):
        """Run the command line; help, click's messages and our errors follow --lang / the locale."""
        lang = _requested_lang(list(sys.argv[1:] if args is None else args))  # args stay as given (click
        # expands wildcards itself on Windows when they are None)
        if lang != "en":
            from .i18n.click_lang import translated

            with translated(self, lang):
                return self._main(args, prog_name, complete_var, standalone_mode, lang, **extra)
        return self._main(args, prog_name, complete_var, standalone_mode, lang, **extra)

    def _main(self, args, prog_name, complete_var, standalone_mode, lang, **extra):
        if not standalone_mode:
            return super().main(args, prog_name, complete_var, standalone_mode, **extra)
        import warnings

        from .output.interrupt import Stopped, handle_signals

        say = _words(lang)
        if not _streams_ready(lang):
            sys.exit(2)
        try:
            with handle_signals(), warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)  # numpy's overflow chatter is never shown
                rv = super().main(args, prog_name or "tmm", complete_var, False, **extra)
        except TmmError as exc:
            _fail(str(exc), lang)
        except click.exceptions.Abort:
            click.echo(f"tmm: {say('aborted')}", err=True)
            sys.exit(1)
        except click.ClickException as exc:
            no_args = getattr(click.exceptions, "NoArgsIsHelpError", ())
            if isinstance(exc, no_args) or (isinstance(exc, click.UsageError) and exc.ctx is not None
                                            and exc.ctx.parent is None and not _command_given(args)):
                click.echo(exc.ctx.get_help())  # bare `tmm`: the help, as `tmm --help` prints it, exit 0
                sys.exit(0)
            _fail(exc.format_message(), lang)
        except Stopped as exc:  # Ctrl-C (130), SIGTERM (143) or SIGHUP (129) during a command, see interrupt.py
            _remove_what_a_stop_left()
            _say_stopped(f"tmm: {say(exc.message)}")
            sys.exit(exc.exit_code)
        except KeyboardInterrupt as exc:  # Ctrl-C (130), SIGTERM (143) or SIGHUP (129), see interrupt.py
            _remove_what_a_stop_left()
            _say_stopped(f"tmm: {say(getattr(exc, 'message', '') or 'interrupted')}")
            sys.exit(getattr(exc, "exit_code", 130))
        except BrokenPipeError:  # `tmm gears | head -1`: the reader has gone; silent, exit 1 (as click does)
            from .output.streams import silence_stdout

            silence_stdout()
            sys.exit(1)
        except OSError as exc:  # the system refused: a full disk, a path too long, stdout on /dev/full
            if os.environ.get("TMM_DEBUG"):
                raise
            from .output.streams import stdout_failed

            where = "standard output" if stdout_failed(exc) else (exc.filename or "")
            _fail(f"cannot write {where} ({exc.strerror or exc.__class__.__name__})" if where else
                  f"the system refused: {exc.strerror or exc}", lang)
        except Exception as exc:  # a bug: one line, not a traceback, unless TMM_DEBUG is set
            if os.environ.get("TMM_DEBUG"):
                raise
            click.echo(f"tmm: {say('internal error')}: {exc.__class__.__name__}: {exc} "
                       f"({say('run with TMM_DEBUG=1 for details')})", err=True)
            sys.exit(1)
        sys.exit(rv if isinstance(rv, int) else 0)

    def invoke(self, ctx):
        try:
            return super().invoke(ctx)
        except KeyboardInterrupt as exc:  # past click's Abort ("Aborted!", exit 1): exit 130 / 143
            from .output.interrupt import Stopped

            raise Stopped(exc) from None
        except Exception:
            from .output.interrupt import Stopped, received

            stop = received()
            if stop is None:
                raise
            raise Stopped(stop) from None  # the error a signal caused: an interruption (see received)


def _streams_ready(lang: str) -> bool:
    """Standard output must be open (False, with one line on stderr, if it is closed); text the
    output's encoding cannot hold is written as near as it can (output/streams.py)."""
    from .i18n import tr
    from .output.streams import stdout_closed, tolerate_narrow_encodings

    tolerate_narrow_encodings()
    if stdout_closed():
        if sys.stderr is not None:
            click.echo("tmm: " + tr(lang, "error: standard output is closed; run tmm with its output going to a "
                                          "terminal, a file or a pipe (e.g. > out.txt)"), err=True)
        return False
    return True


def _say_stopped(line: str) -> None:
    """The one line after a signal; the terminal may be gone (SIGHUP): then nothing."""
    try:
        click.echo(line, err=True)
    except (OSError, ValueError):
        pass


def _remove_what_a_stop_left() -> None:
    """After Ctrl-C/SIGTERM: the staging folders and temporary files this process still has
    registered (a signal between creating one and entering the block that removes it)."""
    files = sys.modules.get("tmm_cli.output.folder")  # nothing was staged if it was never imported
    if files is not None:
        files.remove_active_staging()


def _command_given(args) -> bool:
    """Whether the command line names anything beyond options (`tmm --lang ru` names nothing)."""
    words = list(sys.argv[1:] if args is None else args)
    i = 0
    while i < len(words):
        if words[i] == "--lang":
            i += 2
            continue
        if not words[i].startswith("--lang="):
            return True
        i += 1
    return False


def _requested_lang(args: list[str]) -> str:
    """The language of this run: --lang on the command line (the last one wins), else the locale."""
    lang = None
    for i, a in enumerate(args):
        if a == "--":
            break
        if a == "--lang" and i + 1 < len(args):
            lang = args[i + 1]
        elif a.startswith("--lang="):
            lang = a.split("=", 1)[1]
    if lang in ("ru", "en"):
        return lang
    from .i18n.lang import default_lang

    return default_lang()


def _words(lang: str):
    """The shell's few words ("error", "interrupted" …) in `lang`."""
    from .i18n import tr

    return lambda w: tr(lang, w)


# the shell's words, for the catalogue (they reach _words as variables)
_WORDS = (N_("error"), N_("internal error"), N_("aborted"), N_("interrupted"), N_("run with TMM_DEBUG=1 for details"))


def _fail(message: str, lang: str = "en") -> None:
    from .i18n.errors import translate_error

    from .inputs.names import visible

    line = visible(translate_error(message, lang))  # a path or a name in it: its control characters as codes
    click.echo(f"tmm: {_words(lang)('error')}: {line}", err=True)
    sys.exit(2)


@click.group(cls=TmmGroup, context_settings=CONTEXT)
@click.version_option(package_name="tmm", prog_name="tmm")
@lang_option
def cli(lang):
    """tmm — the calculation part of the TMM course project (Pozhbelko et al., 2003, part 2).

    Sheet 3: cam mechanism synthesis (`tmm cam`). Sheet 4: gear drive synthesis (`tmm gears`).
    Both at once, with a report: `tmm project --variant 17`. Teachers: `tmm assign`, `tmm batch`, `tmm check`.
    """


for _command in (variants_cmd, project_cmd, cam_cmd, gears_cmd, planetary_cmd, linkage_cmd, synth_cmd, note_cmd, assign_cmd, batch_cmd,
                 check_cmd, carrier_cmd, chain_cmd):
    cli.add_command(_command)
apply_option_limits(cli)

main = cli

if __name__ == "__main__":  # pragma: no cover
    cli()
