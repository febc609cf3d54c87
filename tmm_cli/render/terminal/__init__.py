"""The terminal: rich tables and messages, one module per chapter."""


def escape(text) -> str:
    """A person's text (or a path, an error holding one) for rich: its markup escaped (``[/x]`` is
    text) and its control characters shown as codes (inputs/names.visible): the one rule for text
    that reaches the terminal."""
    from rich.markup import escape as markup_escape

    from ...inputs.names import visible

    return markup_escape(visible(text))
