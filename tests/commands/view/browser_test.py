"""glint view in a real browser: headless Chromium (Debian), driven through the DevTools
protocol. The page loads, the image refines, a control restarts the render and changes
it, a bad value gets the command line's message, a click shows a pixel's ray trees, the
URL holds the state, the exposure is the page's own, two browsers share one render, the
compare views and the downloads work.

Usage: browser_test.py GLINT SCENE OUTDIR   (screenshots are left in OUTDIR)
"""
import os
import subprocess
import sys
import time

from glintview import Browser, Server, pixels

GLINT, SCENE, OUT = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(OUT, exist_ok=True)
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def shot(browser, name, selector="#image"):
    png = browser.screenshot(selector)
    with open(os.path.join(OUT, name + ".png"), "wb") as f:
        f.write(png)
    return pixels(png)


def text(browser, element_id):
    return browser.eval(f"document.getElementById('{element_id}').textContent")


def generation(browser):
    return int(browser.eval("document.body.dataset.generation || 0"))


def wait_for_generation_shown(browser, g, timeout=20):
    browser.wait_for(f"Number(document.body.dataset.shownGeneration) === {g}", timeout)


def set_field(browser, name, value):
    browser.eval(f"(() => {{ const el = document.querySelector('[name=\"{name}\"]'); "
                 f"el.value = '{value}'; el.dispatchEvent(new Event('change')); }})()")


def diff(a, b):
    return float(abs(a - b).mean())


server = Server(GLINT, SCENE)  # as a user starts it: the scene's 512x512, Whitted
browser = Browser()
second = None
try:
    # The page loads and shows frames.
    start = time.time()
    browser.open(server.url + "/?mode=mc")
    browser.wait_for("Number(document.body.dataset.frame) > 0")
    check(browser.eval("document.title") == "glint view", "the page loads")
    check("passes" in text(browser, "status"),
          f"first frame after {time.time() - start:.2f} s: {text(browser, 'status')}")

    # The image refines: pixels change between two screenshots a second apart.
    time.sleep(0.5)
    a = shot(browser, "refine-1")
    time.sleep(1.0)
    b = shot(browser, "refine-2")
    changed = float((abs(a - b).sum(axis=2) > 0).mean())
    check(changed > 0.01, f"the image refines: {100 * changed:.1f}% of the pixels changed in 1 s")
    time.sleep(1.0)
    status = text(browser, "status")
    fps = float(status.split(" frames/s")[0].split()[-1])
    check(fps >= 2.0, f"frames per second while passes complete: {status}")
    check("mode=mc" in browser.eval("location.search") and "exposure=" in
          browser.eval("location.search"), f"the URL holds the state: {browser.eval('location.search')}")

    # A control restarts the accumulation at once and changes the image.
    before = shot(browser, "ior-1.5")
    spp_before = int(status.split(" rays/pixel")[0].split()[-1])
    g = generation(browser)
    start = time.time()
    set_field(browser, "tunable:/objects/1/ior", "1.1")
    wait_for_generation_shown(browser, g + 1)
    seconds = time.time() - start
    status = text(browser, "status")
    spp_after = int(status.split(" rays/pixel")[0].split()[-1])
    check(seconds < 3.0, f"O2's index 1.1: its first frame on the page after {seconds:.2f} s")
    check(spp_after < spp_before, f"the accumulation restarted: {spp_before} -> {spp_after} rays/pixel")
    after = shot(browser, "ior-1.1")
    check(diff(before, after) > 1.0, f"the image changed (mean difference {diff(before, after):.2f} levels)")
    check("ior%3D1.1" in browser.eval("location.search"), "the URL has the new index")

    # A bad value: the command line's message on the page, and the render goes on.
    frame = int(browser.eval("document.body.dataset.frame"))
    set_field(browser, "tunable:/objects/1/ior", "0.5")
    browser.wait_for("!document.getElementById('message').hidden")
    message = text(browser, "message")
    check("/objects/1/ior: expected a number >= 1, found the number 0.5" in message,
          f"a bad index gets the command line's message: {message!r}")
    browser.wait_for(f"Number(document.body.dataset.frame) > {frame + 2}")
    check(generation(browser) == g + 1 and server.proc.poll() is None,
          "the server keeps rendering the last good settings")
    shot(browser, "bad-value", "main")

    # A click on the glass sphere shows its ray trees.
    box = browser.eval("(() => { const r = document.getElementById('image')"
                       ".getBoundingClientRect(); return [r.x, r.y, r.width, r.height]; })()")
    browser.click(box[0] + 0.72 * box[2], box[1] + 0.78 * box[3])
    browser.wait_for("document.querySelectorAll('#tree-view .ray-node').length >= 2")
    first = browser.eval("document.querySelector('#tree-view .ray-node').textContent")
    nodes = browser.eval("document.querySelectorAll('#tree-view .ray-node').length")
    check("camera ray" in first and "hits O2" in first,
          f"the glass sphere's tree: {nodes} nodes, the first: {first!r}")
    check("C_R" in text(browser, "tree-title"), f"tree title: {text(browser, 'tree-title')}")
    shot(browser, "tree", "#tree")

    # The exposure is applied on the page: brighter, without a new render.
    g = generation(browser)
    dim = shot(browser, "exposure-1")
    browser.eval("(() => { const e = document.getElementById('exposure'); e.value = '2'; "
                 "e.dispatchEvent(new Event('input')); })()")
    time.sleep(0.3)
    bright = shot(browser, "exposure-4")
    check(bright.mean() > dim.mean() + 10 and generation(browser) == g,
          f"exposure x4: mean level {dim.mean():.1f} -> {bright.mean():.1f}, no re-render")
    check("exposure=4" in browser.eval("location.search"), "the URL has the exposure")

    # Downloads: PNG, PFM, EXR, and a scene file that glint render accepts.
    magic = browser.eval("""(async () => {
        const out = {};
        for (const f of ['png', 'pfm', 'exr']) {
          const b = new Uint8Array(await (await fetch(`/api/image?format=${f}`)).arrayBuffer());
          out[f] = Array.from(b.slice(0, 4));
        }
        out.scene = await (await fetch(document.getElementById('save-scene').href)).text();
        return out; })()""")
    check(magic["png"] == [0x89, 0x50, 0x4E, 0x47], f"PNG download: {magic['png']}")
    check(magic["pfm"][:2] == [0x50, 0x46], f"PFM download: {magic['pfm']}")
    check(magic["exr"] == [0x76, 0x2F, 0x31, 0x01], f"EXR download: {magic['exr']}")
    scene_file = os.path.join(OUT, "saved-scene.json")
    with open(scene_file, "w") as f:
        f.write(magic["scene"])
    run = subprocess.run([GLINT, "render", scene_file, "--mode", "mc", "--size", "16", "--spp", "1",
                          "-o", os.path.join(OUT, "saved-scene.png"), "-q"],
                         capture_output=True, text=True)
    check(run.returncode == 0 and '"ior": 1.1' in magic["scene"],
          f"the saved scene (O2 index 1.1) renders with glint render: exit {run.returncode} {run.stderr}")
    # Two browsers see the same render; a change in one shows in the other.
    second = Browser()
    second.open(server.url + "/")
    second.wait_for("Number(document.body.dataset.frame) > 0")
    check(generation(second) == generation(browser), "a second browser sees the same render")
    g = generation(browser)
    set_field(browser, "sampler", "random")
    wait_for_generation_shown(second, g + 1)
    check(second.eval("document.querySelector('[name=sampler]').value") == "random",
          "the second browser follows a change made in the first")
    second.close()
    second = None

    # ?mode=whitted and ?mode=mc show different images; mc's switches are off in whitted.
    g = server.json("/api/state")[1]["generation"]
    browser.open(server.url + "/?mode=whitted")
    wait_for_generation_shown(browser, g + 1)
    time.sleep(0.5)
    whitted = shot(browser, "mode-whitted")
    disabled = browser.eval("['walls', 'strategy', 'glass', 'branches', 'mirror-light'].every("
                            "(n) => document.querySelector(`[name=${n}]`).disabled)")
    check(disabled, "in Whitted mode the Monte Carlo switches are disabled")
    browser.open(server.url + "/?mode=mc")
    wait_for_generation_shown(browser, g + 2)
    time.sleep(0.5)
    mc = shot(browser, "mode-mc")
    check(diff(whitted, mc) > 5.0, f"?mode=whitted and ?mode=mc differ (mean {diff(whitted, mc):.1f} levels)")
    check(not browser.eval("document.querySelector('[name=walls]').disabled"),
          "in Monte Carlo mode they are enabled")
    # The mirror light means something with diffuse walls only.
    check(browser.eval("document.querySelector('[name=\"mirror-light\"]').disabled"),
          "with terminal walls the mirror light is disabled")
    browser.open(server.url + "/?mode=mc&walls=diffuse&mirror-light=brdf")
    wait_for_generation_shown(browser, g + 3)
    check(browser.eval("!document.querySelector('[name=\"mirror-light\"]').disabled && "
                       "document.querySelector('[name=\"mirror-light\"]').value === 'brdf' && "
                       "document.getElementById('command').textContent.includes("
                       "'--walls diffuse') && document.getElementById('command').textContent"
                       ".includes('--mirror-light brdf')"),
          "with diffuse walls it is enabled, set from the URL, and in the command line")

    check(not browser.console, f"no errors in the page's console: {browser.console}")
finally:
    if second:
        second.close()
    browser.close()
    code, seconds, _ = server.stop()
check(code == 0, f"glint view stopped by SIGTERM: exit {code} after {seconds:.2f} s")

# With a reference: the A/B flip, the relative-error view and the chart.
reference = os.path.join(OUT, "reference.pfm")
subprocess.run([GLINT, "render", SCENE, "--mode", "mc", "--size", "128", "--spp", "256", "-q", "--seed", "7",
                "-o", reference], check=True)
server = Server(GLINT, SCENE, "--mode", "mc", "--size", "128", "--reference", reference)
browser = Browser()
try:
    browser.open(server.url + "/")
    browser.wait_for("!document.getElementById('compare').hidden")
    browser.wait_for("Number(document.body.dataset.frame) > 4")
    render = shot(browser, "compare-render")
    browser.eval("document.getElementById('flip').click()")
    flipped = shot(browser, "compare-reference")
    check(browser.eval("document.querySelector('input[name=show]:checked').value") == "reference",
          f"A/B flip shows the reference (mean difference {diff(render, flipped):.2f} levels)")
    browser.eval("document.querySelector('input[name=show][value=error]').click()")
    error = shot(browser, "compare-error")
    check(diff(error, render) > 20, f"the relative-error view is false colour "
          f"(mean difference {diff(error, render):.1f} levels from the render)")
    time.sleep(1.0)
    chart = shot(browser, "compare-chart", "#chart")
    blue = int(((chart[:, :, 2] > 150) & (chart[:, :, 0] < 100)).sum())
    check(blue > 50, f"the chart draws relative MSE against time ({blue} pixels of its line)")
    check("relative MSE" in text(browser, "status"), f"status: {text(browser, 'status')}")
    shot(browser, "compare-page", "main")

finally:
    browser.close()
    server.stop()

print(f"{len(failures)} failure(s); screenshots in {OUT}")
sys.exit(1 if failures else 0)
