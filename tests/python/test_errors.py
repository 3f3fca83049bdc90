# Errors from Python: the API's exceptions as candela.Error subclasses carrying the command line's
# one-line message; Python's own for a wrong call.
import pytest

import candela


def test_a_missing_file_is_an_input_error_naming_it(device, tmp_path):
    missing = tmp_path / "missing.glb"
    with pytest.raises(candela.InputError) as raised:
        device.load_scene(missing)
    assert raised.value.file == str(missing)
    assert str(raised.value).startswith(f"{missing}: ") and "\n" not in str(raised.value)
    assert isinstance(raised.value, candela.Error) and isinstance(raised.value, RuntimeError)


def test_malformed_bytes_name_the_given_name(device):
    with pytest.raises(candela.InputError, match="^broken.glb: ") as raised:
        device.load_scene(b"glTF\x02\x00\x00\x00", name="broken.glb")
    assert raised.value.file == "broken.glb" and raised.value.reason
    with pytest.raises(candela.InputError, match="^sky.hdr: "):
        device.load_environment(b"#?RADIANCE\n", name="sky.hdr")


def test_bad_settings(device, grid):
    with pytest.raises(TypeError, match="widht"):
        device.render(grid, widht=64)
    with pytest.raises(candela.InputError, match="choose from color"):
        device.render(grid, width=8, height=8, outputs=["colour"])
    with pytest.raises(candela.InputError, match="tonemap 'filmic'"):
        device.render(grid, width=8, height=8, tonemap="filmic")
    with pytest.raises(candela.InputError, match="dtype"):
        device.render(grid, width=8, height=8, dtype="int32")
    with pytest.raises(candela.InputError, match="0x8"):
        device.render(grid, width=0, height=8)
    with pytest.raises(candela.InputError, match="variant"):
        device.render(grid, width=8, height=8, variant="none such")
    with pytest.raises(candela.InputError, match="0 frames"):
        device.render_sequence(grid, frames=0)


def test_a_closed_device_says_so(grid):
    device = candela.Device(pipeline_cache="off")
    device.close()
    assert device.closed
    with pytest.raises(candela.Error, match="closed"):
        device.render(grid, width=8, height=8)
