"""glint-serve's page in a real browser (Debian's chromium, driven through chromedriver by
Selenium): the showcase loads and refines, a drag orbits the camera and changes the image, a
click draws a pixel's ray tree whose numbers are `glint explain --format json`'s, and an edit of
the scene file renders again, a broken one shows its error. Screenshots go to the output folder.

Run by CTest (tests/serve/CMakeLists.txt) with GLINT_SERVE, GLINT_BINARY, GLINT_SOURCE_DIR and
GLINT_TEST_OUTPUT set."""

import json
import os
import pathlib
import re
import shutil
import subprocess
import time

import pytest
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select

SERVE = os.environ["GLINT_SERVE"]
GLINT = os.environ["GLINT_BINARY"]
SOURCE = pathlib.Path(os.environ["GLINT_SOURCE_DIR"])
OUTPUT = pathlib.Path(os.environ["GLINT_TEST_OUTPUT"])


@pytest.fixture(scope="module")
def served():
    """The showcase, copied to a folder of its own, served on a free port."""
    folder = OUTPUT / "browser"
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    scene = folder / "showcase.yaml"
    shutil.copy(SOURCE / "scenes" / "showcase.yaml", scene)
    server = subprocess.Popen([SERVE, str(scene), "--port", "0"], stdout=subprocess.PIPE, text=True)
    line = server.stdout.readline()
    url = re.search(r"http://\S+", line).group(0)
    yield url, scene, folder
    server.terminate()
    assert server.wait(timeout=20) == 0


@pytest.fixture(scope="module")
def browser():
    options = webdriver.ChromeOptions()
    options.binary_location = shutil.which("chromium")
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu",
                     "--disable-dev-shm-usage", "--window-size=1500,900"):
        options.add_argument(argument)
    driver = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)
    yield driver
    driver.quit()


def wait_for(condition, timeout=60, what="the page"):
    end = time.time() + timeout
    while time.time() < end:
        value = condition()
        if value:
            return value
        time.sleep(0.05)
    raise AssertionError(f"timed out waiting for {what}")


def shown_frame(driver):
    """The frame the page shows, once it is its view's last and its image has loaded."""
    body = driver.find_element(By.TAG_NAME, "body")
    sequence = body.get_attribute("data-sequence")
    if body.get_attribute("data-done") != "true" or body.get_attribute("data-shown") != sequence:
        return None
    return int(sequence)


def picture(driver):
    """The pixels of the image on the page, summed per channel: enough to see it change. Waits
    while a next frame's image loads: until then the element has no size."""
    return wait_for(lambda: driver.execute_script("""
        const image = document.getElementById('image');
        if (!image.complete || image.naturalWidth === 0) return null;
        const canvas = document.createElement('canvas');
        canvas.width = image.naturalWidth; canvas.height = image.naturalHeight;
        const context = canvas.getContext('2d');
        context.drawImage(image, 0, 0);
        const data = context.getImageData(0, 0, canvas.width, canvas.height).data;
        const sums = [0, 0, 0];
        for (let i = 0; i < data.length; i += 4) for (let c = 0; c < 3; ++c) sums[c] += data[i + c];
        return sums;"""), what="the image to load")


def next_finished_frame(driver, after):
    return wait_for(lambda: (s := shown_frame(driver)) and s > after and s, what="a new image")


def short(x):
    """A number as the page writes it: six significant digits, as JavaScript prints them."""
    value = float(f"{x:.6g}")
    return str(int(value)) if value.is_integer() else repr(value)


def test_the_page_renders_orbits_explains_and_follows_edits(served, browser):
    url, scene, folder = served
    browser.get(url)
    first = wait_for(lambda: shown_frame(browser), what="the first image")
    status = browser.find_element(By.ID, "status").text
    assert "9 of 9 samples a pixel" in status, status
    browser.save_screenshot(str(folder / "1-loaded.png"))
    before = picture(browser)

    # A drag orbits: a new camera, a new image.
    image = browser.find_element(By.ID, "image")
    ActionChains(browser).move_to_element(image).click_and_hold().move_by_offset(60, 0) \
        .move_by_offset(60, 10).release().perform()
    orbited = next_finished_frame(browser, first)
    assert picture(browser) != before
    browser.save_screenshot(str(folder / "2-orbited.png"))

    # Back to the scene's camera, then a click on the glass sphere.
    browser.find_element(By.ID, "reset-camera").click()
    settled = next_finished_frame(browser, orbited)
    assert picture(browser) == before
    # Offsets are from the image's centre (400, 300): the glass sphere is right of it.
    ActionChains(browser).move_to_element_with_offset(image, 40, 10).click().perform()
    explained = wait_for(lambda: re.match(r"Pixel (\d+), (\d+), sample (\d+)",
                                          browser.find_element(By.ID, "explain-status").text),
                         what="the ray tree")
    x, y, sample = (int(n) for n in explained.groups())
    # The page's layout may put the image at a fraction of a pixel: the click lands within one.
    assert abs(x - 440) <= 1 and abs(y - 310) <= 1 and sample == 0, (x, y, sample)
    lines = browser.find_elements(By.CSS_SELECTOR, "#overlay line")
    assert len(lines) >= 3
    assert browser.find_elements(By.CSS_SELECTOR, "#overlay line.shadow")
    assert browser.find_elements(By.CSS_SELECTOR, "#overlay line.refracted")

    # The numbers on the page are glint explain's for the same pixel and sample.
    tree = json.loads(subprocess.run(
        [GLINT, "explain", str(scene), "--pixel", f"{x},{y}", "--sample", str(sample),
         "--format", "json"], check=True, capture_output=True, text=True).stdout)
    text = browser.find_element(By.ID, "tree").get_attribute("textContent")
    for ray in tree["rays"]:
        assert f"ray {ray['id']}:" in text
        if ray["hit"]:
            assert f"t = {short(ray['hit']['t'])}" in text, ray["id"]
        value = "(" + ", ".join(short(c) for c in ray["value"]) + ")"
        assert value in text, (ray["id"], value)
    assert "sample value = (" + ", ".join(short(c) for c in tree["sample_value"]) + ")" in text

    # Hovering over a ray in the tree thickens its segments.
    summary = browser.find_element(By.CSS_SELECTOR, "#tree details[data-node='0'] > summary")
    ActionChains(browser).move_to_element(summary).perform()
    wait_for(lambda: browser.find_elements(By.CSS_SELECTOR, "#overlay line.highlight"),
             what="a highlighted segment")
    browser.save_screenshot(str(folder / "3-explained.png"))

    # An edit renders again; a broken scene shows its error and keeps the image.
    text = scene.read_text()
    scene.write_text(text.replace("background: [0.32, 0.52, 0.82]",
                                  "background: [0.9, 0.5, 0.2]"))
    edited = next_finished_frame(browser, settled)
    assert picture(browser) != before
    scene.write_text(text.replace("radius: 1.2,", "radius: -1.2,"))
    error = browser.find_element(By.ID, "error")
    # The radius's error: a look at the file between the write's truncation and its text may
    # show the empty file's error first.
    wait_for(lambda: error.is_displayed() and "radius" in error.text, what="the error")
    assert "showcase.yaml:" in error.text and "^" in error.text, error.text
    assert browser.find_element(By.ID, "image").get_attribute("src")
    browser.save_screenshot(str(folder / "4-broken.png"))
    scene.write_text(text)
    next_finished_frame(browser, edited)
    wait_for(lambda: not error.is_displayed(), what="the error to go")
    assert picture(browser) == before

    # A view of an output variable: the render records them all, and the page shows the depth's
    # colour map with its legend below the image; back to the image without rendering again.
    Select(browser.find_element(By.ID, "view-choice")).select_by_value("depth")
    body = browser.find_element(By.TAG_NAME, "body")
    depth = wait_for(lambda: (s := shown_frame(browser)) and
                     body.get_attribute("data-shown-view") == "depth" and s, what="the depth view")
    height = int(body.get_attribute("data-shown-height"))
    assert height > 600, height  # the legend's strip
    assert picture(browser) != before
    browser.save_screenshot(str(folder / "5-depth.png"))
    Select(browser.find_element(By.ID, "view-choice")).select_by_value("image")
    wait_for(lambda: body.get_attribute("data-shown-view") == "image", what="the image again")
    # No render is asked for. On a slow VM a frame later than the depth view's has come here,
    # finished and of the same picture (from what is not yet known: likely the scene's reload
    # after its last edit), so any finished frame from the depth view's on will do.
    assert wait_for(lambda: shown_frame(browser), what="the image's frame") >= depth
    assert picture(browser) == before
