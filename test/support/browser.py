"""Headless Chromium through Selenium (Debian's chromium and chromium-driver),
for the viewer's browser test and the bench: as root it needs --no-sandbox;
its console is kept, for the test to read."""
import os

CHROMEDRIVER = '/usr/bin/chromedriver'


def have_browser():
    return os.path.exists(CHROMEDRIVER)


def browser(profile):
    """A headless Chromium with its own profile folder `profile`."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    for argument in ('--headless=new', '--no-sandbox', '--disable-gpu',
                     f'--user-data-dir={profile}', '--window-size=1000,800'):
        options.add_argument(argument)
    options.set_capability('goog:loggingPrefs', {'browser': 'ALL'})
    return webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
