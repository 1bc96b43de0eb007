import groovy.json.JsonSlurper
def dir = new File(basedir, 'target/fclcert-reports')
['report.json', 'report.md', 'report.html', 'junit.xml', 'results.jsonl'].each {
    assert new File(dir, it).isFile() : "missing $it"
}
def report = new JsonSlurper().parse(new File(dir, 'report.json'))
assert report.iut.name == 'Vendor FCL'
assert report.basicLevel.conformant == true
def nsum = report.features.find { it.id == 'E-ACCU-NSUM' }
assert nsum.status == 'not-realised'
assert report.features.find { it.id == 'E-ACCU-BSUM' }.status == 'realised'
def log = new File(basedir, 'build.log').text
assert log.contains('meets failOn=basic')
assert log.contains('BUILD SUCCESS')
// JUnit agrees with verify: the NSUM cases the vendor does not claim are skipped, not failed
def suite = javax.xml.parsers.DocumentBuilderFactory.newInstance().newDocumentBuilder()
        .parse(new File(basedir, 'target/surefire-reports/TEST-fclcert.xml')).documentElement
assert suite.getAttribute('tests').toInteger() == report.summary.cases
assert suite.getAttribute('failures') == '0' : "unclaimed features are skipped: ${suite.getAttribute('failures')}"
def testcases = suite.getElementsByTagName('testcase')
def nsumCases = (0..<testcases.length).collect { testcases.item(it) }
        .findAll { it.getAttribute('classname') == 'fclcert.E-ACCU-NSUM' }
assert !nsumCases.isEmpty()
// skipped as not claimed, or (a case written in a library's dialect, O-ACCU-NSUM-081) as not presentable to it
assert nsumCases.every {
    def skipped = it.getElementsByTagName('skipped')
    skipped.length == 1 && ['not claimed: Vendor FCL', 'not presentable: '].any { p ->
        skipped.item(0).getAttribute('message').startsWith(p) }
}
assert nsumCases.count { it.getElementsByTagName('skipped').item(0).getAttribute('message')
        .startsWith('not claimed: Vendor FCL') } >= 5
// the surefire-report plugin read the file unrenamed: its page counts every case and lists the feature classes
def html = new File(basedir, 'target/reports/surefire.html')
assert html.isFile() : 'surefire-report wrote no page'
def page = html.text
assert page.contains("<td>${report.summary.cases}</td>")
assert page.contains('fclcert.E-ACCU-NSUM')
assert log.contains("Tests run: ${report.summary.cases}, Failures: 0, Errors: 0, Skipped: ")
