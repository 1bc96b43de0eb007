import groovy.json.JsonSlurper
import java.util.zip.ZipFile

// fclcert-spi was installed as its own artifact: a jar of the SPI package alone, sources, javadoc, a pom without dependencies
def spiDir = new File(localRepositoryPath, "org/fclcert/fclcert-spi/${projectVersion}")
def name = "fclcert-spi-${projectVersion}"
['.jar', '-sources.jar', '-javadoc.jar', '.pom'].each {
    assert new File(spiDir, name + it).isFile() : "missing ${name}${it} in ${spiDir}"
}
def classes = new ZipFile(new File(spiDir, name + '.jar')).entries().toList()*.name.findAll { it.endsWith('.class') }
assert !classes.isEmpty()
assert classes.every { it.startsWith('org/fclcert/iut/spi/') } : "not only the SPI: ${classes}"
assert classes.contains('org/fclcert/iut/spi/FclImplementation.class')
def sources = new ZipFile(new File(spiDir, name + '-sources.jar')).entries().toList()*.name
assert sources.contains('org/fclcert/iut/spi/FclImplementation.java')
def javadoc = new ZipFile(new File(spiDir, name + '-javadoc.jar')).entries().toList()*.name
assert javadoc.contains('org/fclcert/iut/spi/FclImplementation.html')
def pom = javax.xml.parsers.DocumentBuilderFactory.newInstance().newDocumentBuilder()
        .parse(new File(spiDir, name + '.pom')).documentElement
def child = { String tag -> (0..<pom.childNodes.length).collect { pom.childNodes.item(it) }.find { it.nodeName == tag } }
assert child('artifactId').textContent == 'fclcert-spi'
assert child('version').textContent == projectVersion
assert pom.getElementsByTagName('dependency').length == 0 : 'fclcert-spi must depend on nothing'

// the vendor's own implementation, compiled against fclcert-spi only, certified by the plugin: Basic Level conformant
def report = new JsonSlurper().parse(new File(basedir, 'target/fclcert-reports/report.json'))
assert report.iut.name == 'Small FCL'
assert report.iut.command.contains('com.example.small.SmallFcl')
assert report.summary.errored == 0
assert report.basicLevel.conformant == true : report.basicLevel.reason
def valve = report.cases.find { it.id == 'B-COGS-001' }
assert valve.status == 'passed'
def log = new File(basedir, 'build.log').text
assert log.contains('meets failOn=basic')
assert log.contains('BUILD SUCCESS')
